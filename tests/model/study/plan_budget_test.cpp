// The main trials a study asks for are a promise: the plan never presents more, and what the
// experimenter is told before it starts (the most, the simulated estimate) is what then runs. A
// study of "5 main trials and 1 practice" was planned as up to 14 main ones (a stage-two tie
// repeated ten times) and said "at most 15".
#include <gtest/gtest.h>

#include <random>

#include "model/space/simulated_observer.hpp"
#include "model/study/simulated_participant.hpp"
#include "model/study/trial_sequence.hpp"
#include "tests/model/study/study_test_support.hpp"

namespace nibrig::model::study {
namespace {

struct BudgetRun {
  std::size_t main = 0, practice = 0, at_most_before = 0;
};

// One simulated participant through the whole plan, counting what was presented.
BudgetRun run_budget_plan(const StudyDefinition& d, std::uint64_t seed) {
  std::mt19937_64 generator(seed);
  const Eigen::MatrixXd truth = space::random_space(d.dims, d.stimuli.size(), generator);
  TrialSequence sequence(d, seed);
  SimulatedParticipant participant(truth, {}, seed);
  BudgetRun run;
  run.at_most_before = sequence.expected_at_most();
  while (const auto planned = sequence.next()) {
    TrialPrompt prompt;
    prompt.number = sequence.answered() + 1;
    prompt.planned = *planned;
    (planned->practice ? run.practice : run.main) += 1;
    EXPECT_LE(prompt.number, sequence.expected_at_most()) << "a trial beyond the most the prompt says";
    sequence.record(participant.answer(prompt, [](Role) {}).choice);
  }
  return run;
}

TEST(PlanBudget, NoPlanPresentsMoreMainTrialsThanItsBudgetAndTheMostSaidIsTheMostRun) {
  for (const PlanKind plan : {PlanKind::two_stage, PlanKind::adaptive}) {
    for (const std::size_t stimuli : {4u, 5u, 7u}) {
      for (const std::size_t budget : {1u, 2u, 3u, 5u, 9u, 15u, 27u, 60u}) {
        StudyDefinition d = test::definition_of(stimuli, plan);
        d.trials = budget;
        d.practice = 1;
        SCOPED_TRACE(std::string(plan_name(plan)) + ", " + std::to_string(stimuli) + " stimuli, budget " +
                     std::to_string(budget));
        const PlanSizes sizes = plan_sizes(d);
        EXPECT_LE(sizes.main_trials_at_most, budget);
        for (std::uint64_t seed = 1; seed <= 3; ++seed) {
          const BudgetRun run = run_budget_plan(d, seed);
          EXPECT_EQ(run.practice, 1u);
          EXPECT_GE(run.main, 1u);
          EXPECT_LE(run.main, budget);
          EXPECT_LE(run.main + run.practice, run.at_most_before);
          EXPECT_EQ(run.at_most_before, run.practice + sizes.main_trials_at_most);
        }
        // What the form and `experiment run` say before it starts: simulated runs of the same plan.
        const TrialEstimate e = estimate_trials(d, estimate_space(d.dims, d.stimuli.size()), 3, 1);
        EXPECT_LE(e.most, budget + 1);
        EXPECT_LE(e.mean, static_cast<double>(budget + 1));
      }
    }
  }
}

TEST(PlanBudget, TheIssuesStudyOfFiveMainTrialsSaysAtMostSixWithItsPractice) {
  StudyDefinition d = test::definition_of(4);
  d.trials = 5;
  d.practice = 1;
  EXPECT_EQ(TrialSequence(d, 1).expected_at_most(), 6u);
  // A budget the paper's split fits exactly is left as it was: 15 stimuli, the paper's 1966.
  StudyDefinition paper = test::definition_of(15);
  paper.trials = 1966;
  const PlanSizes sizes = plan_sizes(paper);
  const space::TwoStageDesign split = space::two_stage_for_budget(15, 1966);
  EXPECT_EQ(sizes.two_stage.stage_two_triplets, split.stage_two_triplets);
  EXPECT_EQ(sizes.two_stage.stage_two_repetitions, split.stage_two_repetitions);
  EXPECT_EQ(sizes.two_stage.stage_one_fraction, split.stage_one_fraction);
  EXPECT_LE(sizes.main_trials_at_most, 1966u);
}

}  // namespace
}  // namespace nibrig::model::study
