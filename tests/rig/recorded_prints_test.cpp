// The paper's recorded prints found by their names: on glass every VeroClear and DM85 print at 1, 2
// and 4 mm has both recordings; on office DM85 at 2 mm has its friction run but no vibration
// recording, so it is not a print the loop can replay. Files listed by hand from the data's
// folders (../shared/data/piovarci2018/PROVENANCE.md).
#include "rig/recorded_prints.hpp"

#include <gtest/gtest.h>

#include "model/design/design_search.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::rig {
namespace {

TEST(RecordedPrints, TheGridOnGlassHasBothRecordingsOfEveryPrint) {
  const auto data = nibrig::test::shared_data() / "piovarci2018";
  const auto prints = find_recorded_prints(data, "glass", {"vero", "DM85"});
  ASSERT_EQ(prints.size(), 6u);
  const char* expected[][3] = {
      {"vero,tip=1mm", "arm_vero_1_glass.csv.gz", "vero1_glass_2.2N_13.7_1.csv.gz"},
      {"vero,tip=2mm", "arm_vero_2_glass.csv.gz", "vero2_glass_2.2N_13.7_1.csv.gz"},
      {"vero,tip=4mm", "arm_vero_4_glass.csv.gz", "vero4_glass_2.2N_13.8_1.csv.gz"},
      {"DM85,tip=1mm", "arm_DM85_1_glass.csv.gz", "DM851_glass_2.2N_13.3_1.csv.gz"},
      {"DM85,tip=2mm", "arm_DM85_2_glass.csv.gz", "DM852_glass_2.2N_13.3_1.csv.gz"},
      {"DM85,tip=4mm", "arm_DM85_4_glass.csv.gz", "DM854_glass_2.2N_13.5_1.csv.gz"}};
  for (std::size_t i = 0; i < prints.size(); ++i) {
    EXPECT_TRUE(model::design::same_design(prints[i].design,
                                           model::design::parse_design_point(expected[i][0])))
        << i;
    EXPECT_EQ(prints[i].vibration.filename(), expected[i][1]);
    EXPECT_EQ(prints[i].friction.filename(), expected[i][2]);
  }
}

TEST(RecordedPrints, APrintWithoutItsVibrationRecordingIsNotOne) {
  const auto data = nibrig::test::shared_data() / "piovarci2018";
  const auto prints = find_recorded_prints(data, "office", {"vero", "DM85"});
  ASSERT_EQ(prints.size(), 5u);
  for (const auto& p : prints)
    EXPECT_FALSE(
        model::design::same_design(p.design, model::design::parse_design_point("DM85,tip=2mm")));
  // The plain prints, not the nail variants recorded beside them on note.
  const auto on_note = find_recorded_prints(data, "note", {"DM85"});
  ASSERT_EQ(on_note.size(), 3u);
  for (const auto& p : on_note)
    EXPECT_EQ(p.vibration.filename().string().find("nail"), std::string::npos) << p.vibration;
}

TEST(RecordedPrints, NoneFoundIsAnErrorNamingTheFolderAndTheNamesExpected) {
  const auto empty = nibrig::test::scratch_dir("recorded_prints_none");
  try {
    find_recorded_prints(empty, "glass", {"vero", "DM85"});
    FAIL() << "an empty folder gave prints";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(empty.string()), std::string::npos) << what;
    EXPECT_NE(what.find("arm_<material>_<tip>_glass"), std::string::npos) << what;
  }
  EXPECT_THROW(find_recorded_prints(empty / "absent", "glass", {"vero"}), std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::rig
