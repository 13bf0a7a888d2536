// The stimuli of a two-stage experiment's answered lists: a misspelled name in a stage-1 row is
// found from what the plan makes of every list (each triplet presented equally often, each name in
// many triplets) and named with its row, instead of becoming a stimulus of its own.
#include "model/space/two_stage_lists.hpp"

#include <gtest/gtest.h>

#include "model/io/format_error.hpp"

namespace nibrig::model::space {
namespace {

// A stage-1 list as `space plan` makes it: every triplet of 6 stimuli (60), each `repetitions` times.
TrialList planned(int repetitions) {
  TrialList list;
  list.stimuli = {"cryon/office", "stab/office", "vero1/office", "vero2/office", "DM851/office", "DM951/office"};
  list.trials = plan_all_triplets(list.stimuli.size(), repetitions, 7, 1.0);
  list.choices.assign(list.trials.size(), Choice::left);
  return list;
}

// Row `row` of `list` with its reference renamed `name` (a new stimulus of the list).
void misspell(TrialList& list, std::size_t row, const std::string& name) {
  list.stimuli.push_back(name);
  list.trials[row].reference = list.stimuli.size() - 1;
}

std::string refusal(const TrialList& list) {
  try {
    stage_one_stimuli({"stage1.csv"}, {list});
  } catch (const io::FormatError& e) {
    return e.what();
  }
  return {};
}

TEST(TwoStageLists, APlannedListsStimuliAreItsOwnInTheOrderItNamesThem) {
  const TrialList list = planned(2);
  const TwoStageStimuli s = stage_one_stimuli({"stage1.csv"}, {list});
  ASSERT_EQ(s.names.size(), 6u);
  for (const auto& name : list.stimuli) EXPECT_EQ(s.names[s.index.at(name)], name);
}

TEST(TwoStageLists, AMisspelledNameInOneRepetitionIsNamedWithItsRow) {
  TrialList list = planned(2);
  misspell(list, 17, "cryon/ofice");
  const std::string why = refusal(list);
  EXPECT_NE(why.find("stage1.csv"), std::string::npos) << why;
  EXPECT_NE(why.find("trial row 18"), std::string::npos) << why;  // the misspelled row, not its twin
  EXPECT_NE(why.find("presented 1 times"), std::string::npos) << why;
}

TEST(TwoStageLists, AMisspelledNameInEveryRepetitionOfItsTripletIsFoundByHowRarelyItIsNamed) {
  TrialList list = planned(1);
  misspell(list, 4, "stab/offic");
  const std::string why = refusal(list);
  EXPECT_NE(why.find("trial row 5"), std::string::npos) << why;
  EXPECT_NE(why.find("'stab/offic' is named in this stage-1 triplet only"), std::string::npos) << why;
  // Each of 6 stimuli is the reference of C(5,2) = 10 triplets and in 20 more as a candidate; the
  // row's own reference lost one of its 30.
  EXPECT_NE(why.find("every other stimulus in 29 triplets or more"), std::string::npos) << why;
}

TEST(TwoStageLists, ATinyListIsNotJudgedByCounts) {
  // Four stimuli, a third of their 12 triplets: names can be in one triplet without a typo.
  TrialList list;
  list.stimuli = {"a", "b", "c", "d"};
  list.trials = plan_all_triplets(4, 1, 3, 0.34);
  EXPECT_EQ(refusal(list), "");
}

TEST(TwoStageLists, AStageTwoNameStageOneLacksIsRefusedWithItsRow) {
  TrialList one = planned(2);
  TrialList two;
  two.stimuli = {"cryon/office", "stab/office", "vero3/office"};
  two.trials = {{0, 1, 2, 2}};
  const TwoStageStimuli s = stage_one_stimuli({"stage1.csv"}, {one});
  try {
    into_stage_one_stimuli(two, "stage2.csv", s);
    ADD_FAILURE() << "accepted";
  } catch (const io::FormatError& e) {
    EXPECT_NE(std::string(e.what()).find("stage2.csv"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("'vero3/office'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace nibrig::model::space
