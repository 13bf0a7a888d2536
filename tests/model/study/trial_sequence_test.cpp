#include "model/study/trial_sequence.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <tuple>

#include "model/space/simulated_observer.hpp"
#include "tests/model/study/study_test_support.hpp"

namespace nibrig::model::study {
namespace {

using TripletKey = std::tuple<std::size_t, std::size_t, std::size_t>;
TripletKey unordered(const space::Trial& t) {
  return {t.reference, std::min(t.left, t.right), std::max(t.left, t.right)};
}

// Runs a whole sequence with an observer of `truth`; returns the sequence.
TrialSequence answered_by(const StudyDefinition& d, const Eigen::MatrixXd& truth, std::uint64_t seed) {
  TrialSequence sequence(d, seed);
  const space::SimulatedObserver observer(truth);
  std::mt19937_64 generator(seed + 1000);
  while (const auto planned = sequence.next()) {
    const auto& t = planned->trial;
    sequence.record(observer.chooses_first(t.reference, t.left, t.right, generator)
                        ? space::Choice::left
                        : space::Choice::right);
  }
  return sequence;
}

Eigen::MatrixXd random_truth(std::size_t stimuli, std::uint64_t seed) {
  std::mt19937_64 generator(seed);
  return space::random_space(2, stimuli, generator);
}

TEST(TrialSequence, TwoStageHasThePapersSizesAndRepeatsTheTiesOfStageOne) {
  // 15 stimuli, the paper's plan: stage 1 half of the 1365 triplets twice (683 × 2 = 1366 trials),
  // stage 2 ten presentations of each of at most 60 ties (Sec. 4.2); 3 practice trials first.
  StudyDefinition d = test::definition_of(15);
  const TrialSequence s = answered_by(d, random_truth(15, 3), 7);
  std::size_t practice = 0, one = 0, two = 0;
  std::map<TripletKey, std::pair<int, int>> stage_one;  // left/right wins per triplet
  std::map<TripletKey, int> stage_two;
  for (std::size_t i = 0; i < s.trials().size(); ++i) {
    const auto& p = s.trials()[i];
    if (p.practice) {
      ++practice;
      EXPECT_EQ(i, practice - 1) << "practice comes first";
      continue;
    }
    if (p.trial.stage == 1) {
      ++one;
      auto& c = stage_one[unordered(p.trial)];
      const std::size_t chosen = s.choices()[i] == space::Choice::left ? p.trial.left : p.trial.right;
      (chosen == std::get<1>(unordered(p.trial)) ? c.first : c.second)++;
    } else {
      ++two;
      ++stage_two[unordered(p.trial)];
    }
  }
  EXPECT_EQ(practice, 3u);
  EXPECT_EQ(one, 1366u);
  std::size_t ties = 0;
  for (const auto& [key, c] : stage_one) ties += std::abs(c.first - c.second) <= 1 ? 1 : 0;
  EXPECT_EQ(two, 10 * std::min<std::size_t>(ties, 60));
  for (const auto& [key, n] : stage_two) {
    EXPECT_EQ(n, 10);
    const auto& c = stage_one.at(key);  // a stage-two triplet was a stage-one tie
    EXPECT_LE(std::abs(c.first - c.second), 1);
  }
  EXPECT_EQ(s.expected_at_most(), s.answered()) << "once stage 2 is planned the count is exact";
}

TEST(TrialSequence, TheSameSeedAndAnswersGiveTheSameTrialsAndAnotherSeedOthers) {
  const StudyDefinition d = test::definition_of(8);
  const Eigen::MatrixXd truth = random_truth(8, 5);
  const TrialSequence a = answered_by(d, truth, 11), b = answered_by(d, truth, 11),
                      c = answered_by(d, truth, 12);
  ASSERT_EQ(a.trials().size(), b.trials().size());
  for (std::size_t i = 0; i < a.trials().size(); ++i) {
    EXPECT_EQ(a.trials()[i].trial.reference, b.trials()[i].trial.reference);
    EXPECT_EQ(a.trials()[i].trial.left, b.trials()[i].trial.left);
    EXPECT_EQ(a.trials()[i].trial.right, b.trials()[i].trial.right);
  }
  std::size_t same = 0;
  for (std::size_t i = 0; i < std::min(a.trials().size(), c.trials().size()); ++i)
    same += a.trials()[i].trial.reference == c.trials()[i].trial.reference &&
            a.trials()[i].trial.left == c.trials()[i].trial.left;
  // 8 references and 7 left candidates: a chance match is about 1 in 56.
  EXPECT_LT(same, a.trials().size() / 5);
}

TEST(TrialSequence, AdaptiveSpendsExactlyItsBudgetOnDistinctInformativeBatches) {
  StudyDefinition d = test::definition_of(8, PlanKind::adaptive);
  d.trials = 150;
  d.practice = 2;
  const TrialSequence s = answered_by(d, random_truth(8, 9), 3);
  EXPECT_EQ(s.answered(), 152u);
  const PlanSizes sizes = plan_sizes(d);
  EXPECT_EQ(sizes.adaptive_initial, 30u);  // a fifth of 150
  EXPECT_EQ(sizes.adaptive_batch, 15u);    // a tenth
  // Within a batch each triplet is asked once (select_batch takes each candidate at most once).
  std::map<int, std::set<TripletKey>> batches;
  for (const auto& p : s.trials())
    if (!p.practice) {
      EXPECT_TRUE(batches[p.trial.stage].insert(unordered(p.trial)).second);
    }
  EXPECT_EQ(batches[1].size(), 30u);
  EXPECT_EQ(batches.size(), 1u + 120u / 15u);
}

TEST(TrialSequence, ValidationAsksEveryPairAgainstTheReferenceWithSidesBalanced) {
  StudyDefinition d = test::definition_of(6);
  d.mode = StudyMode::validation;
  d.practice = 0;
  d.trials = 20;  // two rounds of the 10 pairs of candidates 1-5
  const TrialSequence s = answered_by(d, random_truth(6, 1), 4);
  ASSERT_EQ(s.answered(), 20u);
  std::map<TripletKey, int> asked;
  std::map<TripletKey, int> left_first;
  for (const auto& p : s.trials()) {
    EXPECT_EQ(p.trial.reference, 0u);
    ++asked[unordered(p.trial)];
    left_first[unordered(p.trial)] += p.trial.left < p.trial.right ? 1 : 0;
  }
  EXPECT_EQ(asked.size(), 10u);
  for (const auto& [key, n] : asked) {
    EXPECT_EQ(n, 2);
    EXPECT_EQ(left_first[key], 1) << "each pair once each way round";
  }
}

TEST(TrialSequence, AListedPlanIsPresentedAsListed) {
  StudyDefinition d = test::definition_of(4, PlanKind::file);
  d.practice = 0;
  d.listed_trials = {{0, 1, 2, 1}, {3, 2, 0, 1}, {1, 3, 0, 2}};
  const TrialSequence s = answered_by(d, random_truth(4, 1), 4);
  ASSERT_EQ(s.answered(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(s.trials()[i].trial.reference, d.listed_trials[i].reference);
    EXPECT_EQ(s.trials()[i].trial.left, d.listed_trials[i].left);
    EXPECT_EQ(s.trials()[i].trial.stage, d.listed_trials[i].stage);
  }
}

TEST(TrialSequence, RefusesAnAnswerOfNoneAndAnAnswerAfterTheEnd) {
  StudyDefinition d = test::definition_of(3, PlanKind::file);
  d.practice = 0;
  d.listed_trials = {{0, 1, 2, 1}};
  TrialSequence s(d, 1);
  EXPECT_THROW(s.record(space::Choice::none), std::invalid_argument);
  s.record(space::Choice::left);
  EXPECT_FALSE(s.next());
  EXPECT_THROW(s.record(space::Choice::left), std::logic_error);
}

}  // namespace
}  // namespace nibrig::model::study
