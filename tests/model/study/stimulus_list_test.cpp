#include "model/study/stimulus_list.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "model/io/format_error.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::study {
namespace {

TEST(StimulusList, ReadsPairingsAndNamedDesignPointsSkippingComments) {
  const auto file = nibrig::test::scratch_dir("stimulus_list") / "stimuli.txt";
  std::ofstream(file) << "# the study's tools\ncryon/office\n\n  stab / note  \n"
                         "D1 = DM85:0.5,vero:0.5,tip=2mm/glass\nplain = vero2/office\n";
  const auto list = read_stimulus_list(file);
  ASSERT_EQ(list.size(), 4u);
  EXPECT_EQ(list[0].name, "cryon/office");
  EXPECT_EQ(list[1].tool, "stab");
  EXPECT_EQ(list[1].surface, "note");
  EXPECT_EQ(list[1].name, "stab/note");
  // "tip=2mm" holds an '=' too, but after the point's ':' and ',': only the first names.
  EXPECT_EQ(list[2].name, "D1");
  EXPECT_EQ(list[2].tool, "DM85:0.5,vero:0.5,tip=2mm");
  EXPECT_EQ(list[2].surface, "glass");
  EXPECT_EQ(list[3].name, "plain");
  EXPECT_EQ(pairing_of(list[3]), "vero2/office");
}

TEST(StimulusList, RefusesWhatAStudyCannotUseNamingTheFileAndLine) {
  const auto dir = nibrig::test::scratch_dir("stimulus_list_bad");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"cryon/office\nstab\nvero2/office\n", "line 2: expected TOOL/SURFACE"},
      {"cryon/office\nDM85:0.5,vero:0.5,tip=2mm/glass\nvero2/office\n", "give it a short name"},
      {"cryon/office\nstab/note\ncryon/office\n", "line 3: stimulus 'cryon/office' is listed twice"},
      {"cryon/office\nstab/note\n", "expected at least 3 stimuli"},
      {"cryon/office\n/note\nvero2/office\n", "line 2"},
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const auto file = dir / ("bad" + std::to_string(i) + ".txt");
    std::ofstream(file) << cases[i].first;
    try {
      read_stimulus_list(file);
      ADD_FAILURE() << "accepted: " << cases[i].first;
    } catch (const io::FormatError& e) {
      EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(cases[i].second), std::string::npos) << e.what();
    }
  }
  // `space plan` takes any names.
  std::ofstream(dir / "names.txt") << "a\nb c\nd\n";
  EXPECT_EQ(read_stimulus_names(dir / "names.txt").size(), 3u);
}

}  // namespace
}  // namespace nibrig::model::study
