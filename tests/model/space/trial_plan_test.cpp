#include "model/space/trial_plan.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <random>
#include <set>
#include <tuple>

#include "model/io/format_error.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::space {
namespace {

using Key = std::tuple<std::size_t, std::size_t, std::size_t>;
Key key(std::size_t r, std::size_t x, std::size_t y) { return {r, std::min(x, y), std::max(x, y)}; }

io::Triplet counts(std::size_t r, std::size_t a, std::size_t b, int ca, int cb) {
  io::Triplet t;
  t.reference = r, t.a = a, t.b = b, t.count_a = ca, t.count_b = cb;
  return t;
}

// |left − right| per stimulus over a whole list.
std::vector<long> side_imbalance(const std::vector<Trial>& trials, std::size_t stimuli) {
  std::vector<long> imbalance(stimuli, 0);
  for (const Trial& t : trials) {
    ++imbalance[t.left];
    --imbalance[t.right];
  }
  return imbalance;
}

TEST(TrialPlan, FifteenStimuliHave1365DistinctTriplets) {
  // n·C(n−1, 2) = 15·91 = 1365, the paper's count (Sec. 4.3); exact integers.
  EXPECT_EQ(triplet_count(15), 1365u);
  const auto all = all_triplets(15);
  ASSERT_EQ(all.size(), 1365u);
  std::set<Key> distinct;
  for (const auto& t : all) {
    EXPECT_LT(t.a, t.b);
    EXPECT_NE(t.reference, t.a);
    EXPECT_NE(t.reference, t.b);
    distinct.insert(key(t.reference, t.a, t.b));
  }
  EXPECT_EQ(distinct.size(), 1365u);
  EXPECT_EQ(triplet_count(3), 3u);  // 3 references × the one remaining pair
}

TEST(TrialPlan, EveryTripletAppearsRepetitionsTimesWithBothSidesEqually) {
  const auto trials = plan_all_triplets(15, 2, 7);
  ASSERT_EQ(trials.size(), 2730u);          // 1365 × 2, exact
  std::map<Key, std::pair<int, int>> seen;  // (times, times the smaller candidate was left)
  for (const Trial& t : trials) {
    EXPECT_EQ(t.stage, 1);
    auto& [times, smaller_left] = seen[key(t.reference, t.left, t.right)];
    ++times;
    if (t.left < t.right) ++smaller_left;
  }
  ASSERT_EQ(seen.size(), 1365u);
  for (const auto& [k, v] : seen) {
    EXPECT_EQ(v.first, 2);   // exactly the repetitions asked for
    EXPECT_EQ(v.second, 1);  // an even count splits evenly: once on each side
  }
  for (long d : side_imbalance(trials, 15)) EXPECT_EQ(d, 0);
}

TEST(TrialPlan, OddRepetitionsKeepEveryStimulusWithinOneOfBalanced) {
  for (int repetitions : {1, 3}) {
    for (double fraction : {1.0, 0.5, 0.1}) {
      const auto trials = plan_all_triplets(15, repetitions, 11, fraction);
      std::map<Key, int> smaller_left;
      for (const Trial& t : trials)
        smaller_left[key(t.reference, t.left, t.right)] += t.left < t.right;
      for (const auto& [k, n] : smaller_left) {
        // ⌊r/2⌋ on each side plus the one extra on either.
        EXPECT_GE(n, repetitions / 2);
        EXPECT_LE(n, repetitions / 2 + 1);
      }
      // The Euler orientation guarantees ±1 per stimulus, not just on average.
      for (long d : side_imbalance(trials, 15))
        EXPECT_LE(std::abs(d), 1) << repetitions << " repetitions, fraction " << fraction;
    }
  }
}

TEST(TrialPlan, HalfTheTripletsTwiceAsInThePaper) {
  const auto trials = plan_all_triplets(15, 2, 3, 0.5);
  std::set<Key> distinct;
  for (const Trial& t : trials) distinct.insert(key(t.reference, t.left, t.right));
  EXPECT_EQ(distinct.size(), 683u);  // round(1365 / 2), exact
  EXPECT_EQ(trials.size(), 1366u);
}

TEST(TrialPlan, OrderIsRandomButReproducible) {
  const auto a = plan_all_triplets(15, 2, 5), b = plan_all_triplets(15, 2, 5);
  const auto c = plan_all_triplets(15, 2, 6);
  auto same = [](const std::vector<Trial>& x, const std::vector<Trial>& y) {
    for (std::size_t i = 0; i < x.size(); ++i)
      if (x[i].reference != y[i].reference || x[i].left != y[i].left || x[i].right != y[i].right)
        return false;
    return x.size() == y.size();
  };
  EXPECT_TRUE(same(a, b));   // same seed, same list
  EXPECT_FALSE(same(a, c));  // another seed, another order
  // In a shuffled list the two presentations of a triplet are neighbours with probability
  // 2/2729 each, about one pair in all; 10 would mean the list was not shuffled.
  int adjacent = 0;
  for (std::size_t i = 1; i < a.size(); ++i)
    adjacent += key(a[i].reference, a[i].left, a[i].right) ==
                key(a[i - 1].reference, a[i - 1].left, a[i - 1].right);
  EXPECT_LT(adjacent, 10);
}

TEST(TrialPlan, MergeCountsEveryAnsweredTrial) {
  const auto trials = plan_all_triplets(8, 3, 2);
  std::mt19937_64 generator(9);
  std::vector<Choice> choices;
  std::map<Key, std::pair<int, int>> expected;  // counted here trial by trial
  std::size_t answered = 0;
  for (const Trial& t : trials) {
    const int roll = static_cast<int>(generator() % 5);
    const Choice c = roll == 0 ? Choice::none : roll % 2 ? Choice::left : Choice::right;
    choices.push_back(c);
    if (c == Choice::none) continue;
    ++answered;
    const std::size_t chosen = c == Choice::left ? t.left : t.right;
    auto& e = expected[key(t.reference, t.left, t.right)];
    ++(chosen == std::min(t.left, t.right) ? e.first : e.second);
  }
  const auto merged = merge_trials(trials, choices);
  std::size_t total = 0;
  ASSERT_EQ(merged.size(), expected.size());
  for (const auto& t : merged) {
    EXPECT_LT(t.a, t.b);
    const auto& e = expected.at(key(t.reference, t.a, t.b));
    EXPECT_EQ(t.count_a, e.first);
    EXPECT_EQ(t.count_b, e.second);
    total += static_cast<std::size_t>(t.count_a + t.count_b);
  }
  EXPECT_EQ(total, answered);  // every answer counted once, unanswered trials none
  EXPECT_TRUE(merge_trials(trials, choices, 2).empty());  // no stage-2 trial in the list
  EXPECT_THROW(merge_trials(trials, {}), std::invalid_argument);
}

TEST(TrialPlan, TieRuleOnHandMadeCounts) {
  const TieRule rule;                                 // |count_a − count_b| <= 1
  EXPECT_TRUE(is_tie(counts(0, 1, 2, 1, 1), rule));   // the paper's 1-1
  EXPECT_FALSE(is_tie(counts(0, 1, 2, 2, 0), rule));  // unanimous
  EXPECT_FALSE(is_tie(counts(0, 1, 2, 0, 2), rule));
  EXPECT_TRUE(is_tie(counts(0, 1, 2, 2, 1), rule));  // odd count: the closest split
  EXPECT_FALSE(is_tie(counts(0, 1, 2, 6, 4), rule));
  EXPECT_TRUE(is_tie(counts(0, 1, 2, 1, 0), rule));   // one answer shows nothing obvious
  EXPECT_FALSE(is_tie(counts(0, 1, 2, 0, 0), rule));  // never judged
  EXPECT_FALSE(is_tie(counts(0, 1, 2, 2, 1), TieRule{0}));
  const auto ties = select_ties(
      {counts(0, 1, 2, 1, 1), counts(1, 0, 2, 2, 0), counts(2, 0, 1, 0, 2), counts(3, 0, 1, 1, 1)});
  ASSERT_EQ(ties.size(), 2u);
  EXPECT_EQ(ties[0].reference, 0u);
  EXPECT_EQ(ties[1].reference, 3u);
}

TEST(TrialPlan, StageTwoRepeatsAtMostTheCapTenTimes) {
  std::vector<io::Triplet> ties;
  for (const auto& t : all_triplets(8)) ties.push_back(counts(t.reference, t.a, t.b, 1, 1));
  ties.resize(100);
  std::set<Key> tie_keys;
  for (const auto& t : ties) tie_keys.insert(key(t.reference, t.a, t.b));
  const auto trials = plan_stage_two(ties, 10, 4, 60);
  ASSERT_EQ(trials.size(), 600u);  // 60 × 10, the paper's stage 2
  std::map<Key, std::pair<int, int>> seen;
  for (const Trial& t : trials) {
    EXPECT_EQ(t.stage, 2);
    auto& [times, smaller_left] = seen[key(t.reference, t.left, t.right)];
    ++times;
    smaller_left += t.left < t.right;
  }
  EXPECT_EQ(seen.size(), 60u);
  for (const auto& [k, v] : seen) {
    EXPECT_TRUE(tie_keys.count(k));  // only ties are repeated
    EXPECT_EQ(v.first, 10);
    EXPECT_EQ(v.second, 5);
  }
  EXPECT_EQ(plan_stage_two(ties, 10, 4).size(), 1000u);  // no cap: every tie
}

TEST(TrialPlan, TwoStageCountsFollowThePaper) {
  const std::vector<io::Triplet> one = {counts(0, 1, 2, 1, 1),   // tie, repeated in stage 2
                                        counts(1, 0, 2, 1, 1),   // tie, not repeated: dropped
                                        counts(2, 0, 1, 2, 0),   // clear: kept
                                        counts(3, 0, 1, 0, 2)};  // clear: kept
  const std::vector<io::Triplet> two = {counts(0, 2, 1, 3, 7)};  // candidates in the other order
  const auto fit = two_stage_counts(one, two);
  ASSERT_EQ(fit.size(), 3u);
  EXPECT_EQ(fit[0].reference, 0u);
  EXPECT_EQ(fit[0].a, 1u);  // stored as a < b with the counts swapped along
  EXPECT_EQ(fit[0].count_a, 7);
  EXPECT_EQ(fit[0].count_b, 3);  // stage-one 1-1 not added
  EXPECT_EQ(fit[1].reference, 2u);
  EXPECT_EQ(fit[2].reference, 3u);
}

std::vector<std::string> names(std::size_t n) {
  std::vector<std::string> s;
  for (std::size_t i = 0; i < n; ++i) s.push_back("tool " + std::to_string(i));
  return s;
}

TEST(TrialPlanCsv, RoundTripKeepsTrialsAndAnswers) {
  const auto dir = nibrig::test::scratch_dir("trial_plan_round_trip");
  TrialList list;
  list.stimuli = names(6);
  list.trials = plan_all_triplets(6, 1, 3, 0.5);
  const auto two = plan_stage_two(all_triplets(6), 2, 3, 4);
  list.trials.insert(list.trials.end(), two.begin(), two.end());
  for (std::size_t i = 0; i < list.trials.size(); ++i)
    list.choices.push_back(i % 3 == 0 ? Choice::none : i % 3 == 1 ? Choice::left : Choice::right);
  write_trial_csv(dir / "plan.csv", list);

  for (const auto& known : {list.stimuli, std::vector<std::string>{}}) {
    const TrialList back = read_trial_csv(dir / "plan.csv", known);
    ASSERT_EQ(back.trials.size(), list.trials.size());
    ASSERT_EQ(back.choices.size(), list.trials.size());
    for (std::size_t i = 0; i < list.trials.size(); ++i) {
      // Indices may be renumbered without the known names: compare by name.
      EXPECT_EQ(back.stimuli[back.trials[i].reference], list.stimuli[list.trials[i].reference]);
      EXPECT_EQ(back.stimuli[back.trials[i].left], list.stimuli[list.trials[i].left]);
      EXPECT_EQ(back.stimuli[back.trials[i].right], list.stimuli[list.trials[i].right]);
      EXPECT_EQ(back.trials[i].stage, list.trials[i].stage);
      EXPECT_EQ(back.choices[i], list.choices[i]);
    }
  }
  // A list handed out unanswered is written with an empty chosen column.
  write_trial_csv(dir / "blank.csv", {list.stimuli, list.trials, {}});
  for (Choice c : read_trial_csv(dir / "blank.csv", list.stimuli).choices)
    EXPECT_EQ(c, Choice::none);
}

class TrialPlanCsvMalformed : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = nibrig::test::scratch_dir("trial_plan_malformed"); }
  std::string error_of(const std::string& text, const std::vector<std::string>& known = {}) {
    const auto file = dir_ / "bad.csv";
    std::ofstream(file) << text;
    try {
      read_trial_csv(file, known);
    } catch (const io::FormatError& e) {
      return e.what();
    }
    return "no error";
  }
  std::filesystem::path dir_;
};

TEST_F(TrialPlanCsvMalformed, ErrorsNameFileLineAndWhatWasExpected) {
  const std::string header = "trial,stage,reference,left,right,chosen\n";
  using ::testing::AllOf;
  using ::testing::HasSubstr;
  EXPECT_THAT(error_of(header + "1,1,x,y,z,left\n2,1,x,z,y,maybe\n"),
              AllOf(HasSubstr("bad.csv"), HasSubstr("line 3"), HasSubstr("'chosen'"),
                    HasSubstr("expected left, right or an empty field"), HasSubstr("maybe")));
  EXPECT_THAT(error_of(header + "1,1,x,y,x,\n"),
              AllOf(HasSubstr("line 2"), HasSubstr("three different stimuli")));
  EXPECT_THAT(error_of(header + "1,1,x,y,z,\n1,1,x,z,y,\n"),
              AllOf(HasSubstr("line 3"), HasSubstr("'trial'"), HasSubstr("appears twice")));
  EXPECT_THAT(error_of(header + "1,0,x,y,z,\n"),
              AllOf(HasSubstr("line 2"), HasSubstr("'stage'"), HasSubstr("expected a stage >= 1")));
  EXPECT_THAT(error_of(header + "1,1,x,y,w,\n", {"x", "y", "z"}),
              AllOf(HasSubstr("line 2"), HasSubstr("'right'"), HasSubstr("unknown stimulus")));
  EXPECT_THAT(error_of(header + "1,1,x,y\n"),
              AllOf(HasSubstr("line 2"), HasSubstr("expected 6 fields")));
  EXPECT_THAT(error_of("trial,stage,reference,left\n"), AllOf(HasSubstr("missing column 'right'")));
  EXPECT_THAT(error_of(header + "one,1,x,y,z,\n"),
              AllOf(HasSubstr("line 2"), HasSubstr("'trial'")));
}

TEST(TrialPlan, BadArgumentsAreRejected) {
  EXPECT_THROW(plan_all_triplets(2, 1, 1), std::invalid_argument);
  EXPECT_THROW(plan_all_triplets(5, 0, 1), std::invalid_argument);
  EXPECT_THROW(plan_all_triplets(5, 1, 1, 0.0), std::invalid_argument);
  EXPECT_THROW(plan_all_triplets(5, 1, 1, 1.5), std::invalid_argument);
  EXPECT_THROW(plan_stage_two({}, 0), std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::model::space
