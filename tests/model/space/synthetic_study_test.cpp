#include "model/space/synthetic_study.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace nibrig::model::space {
namespace {

TEST(SyntheticStudy, RecoveryErrorOfTheTruthItselfIsZeroAndOfAStretchIsItsSize) {
  std::mt19937_64 generator(5);
  const Eigen::MatrixXd truth = random_space(2, 10, generator);
  Eigen::Matrix2d rotation;
  rotation << std::cos(1.0), -std::sin(1.0), std::sin(1.0), std::cos(1.0);
  const Eigen::MatrixXd moved = (rotation * truth).colwise() + Eigen::Vector2d(2.0, -1.0);
  const RecoveryError same = recovery_error(moved, truth);
  EXPECT_NEAR(same.coordinates, 0.0, 1e-12);    // Procrustes undoes it up to round-off
  EXPECT_NEAR(same.probabilities, 0.0, 1e-12);  // distances are unchanged by a rigid motion
  // Stretched by 1.5 about the centroid: the best rigid fit leaves exactly 0.5 of the spread.
  const Eigen::MatrixXd centred = truth.colwise() - truth.rowwise().mean();
  const RecoveryError stretched = recovery_error(1.5 * centred, truth);
  EXPECT_NEAR(stretched.coordinates, 0.5, 1e-12);
  EXPECT_GT(stretched.probabilities, 0.01);  // larger differences: clearer predicted outcomes
}

TEST(SyntheticStudy, TheTwoStagePlanHasThePapersSizes) {
  std::mt19937_64 generator(8);
  const SimulatedObserver observer(random_space(2, 15, generator));
  const SimulatedExperiment experiment = simulate_two_stage(observer, {}, 4);
  // The default truth makes ~30 % of the 683 stage-one triplets split 1-1, far more than the 60
  // places, so stage 2 is full: 1366 + 600 trials exactly.
  EXPECT_GT(experiment.ties, 60u);
  EXPECT_EQ(experiment.trials, 1966u);
  std::size_t judgments = 0;
  for (const auto& t : experiment.counts)
    judgments += static_cast<std::size_t>(t.count_a + t.count_b);
  // Stage 2's 600 plus two per non-tie stage-one triplet.
  EXPECT_EQ(judgments, 600u + 2u * (683u - experiment.ties));

  const TwoStageDesign paper = two_stage_for_budget(15, 1966);
  EXPECT_NEAR(paper.stage_one_fraction, 0.5, 0.001);  // 1366 / 2730
  EXPECT_EQ(paper.stage_two_triplets, 60u);
}

TEST(SyntheticStudy, SmallStudyRecoversTheSpaceWellUnderThePapersError) {
  SyntheticStudyOptions options;
  options.trials = 6;
  options.dims = {2};
  options.threads = 2;
  options.fit_starts = 2;
  const auto results = run_synthetic_study(options);
  ASSERT_EQ(results.size(), 1u);
  ASSERT_EQ(results[0].per_trial.size(), 6u);
  // The paper's 17 % is the error of predicting real judgments; the model's own predictions
  // recovered from ~1300 simulated judgments miss the true probabilities by under 10 % (measured
  // ~8.5 % ± 1 %; the paper's data selection stretches the space, see FitData).
  EXPECT_LT(results[0].probability_error.mean, 0.10);
  EXPECT_GT(results[0].probability_error.mean, 0.0);
  // Using every judgment removes the stretch: the coordinates come back to ~15 % of the spread.
  options.design.fit_data = FitData::all_judgments;
  const auto all = run_synthetic_study(options);
  EXPECT_LT(all[0].probability_error.mean, 0.06);
  EXPECT_LT(all[0].coordinate_error.mean, 0.25);
  EXPECT_LT(all[0].coordinate_error.mean, results[0].coordinate_error.mean);
}

TEST(SyntheticStudy, ResultsDoNotDependOnTheThreadCount) {
  SyntheticStudyOptions options;
  options.trials = 3;
  options.dims = {1, 2};
  options.stimuli = 8;
  options.fit_starts = 1;
  options.threads = 1;
  const auto one = run_synthetic_study(options);
  options.threads = 3;
  const auto three = run_synthetic_study(options);
  for (std::size_t d = 0; d < one.size(); ++d)
    for (std::size_t t = 0; t < one[d].per_trial.size(); ++t) {
      // Per-trial seeds: bit-identical, not merely close.
      EXPECT_EQ(one[d].per_trial[t].coordinates, three[d].per_trial[t].coordinates);
      EXPECT_EQ(one[d].per_trial[t].probabilities, three[d].per_trial[t].probabilities);
    }
}

TEST(SyntheticStudy, Summary) {
  const Summary s = summarize({1.0, 2.0, 3.0, 4.0});
  EXPECT_DOUBLE_EQ(s.mean, 2.5);
  EXPECT_NEAR(s.sd, std::sqrt(5.0 / 3.0), 1e-15);  // sample sd, n − 1
  EXPECT_EQ(summarize({7.0}).sd, 0.0);
}

TEST(SyntheticStudy, BadOptionsAreRejected) {
  SyntheticStudyOptions options;
  options.dims = {0};
  EXPECT_THROW(run_synthetic_study(options), std::invalid_argument);
  options.dims = {5};
  options.stimuli = 5;
  EXPECT_THROW(run_synthetic_study(options), std::invalid_argument);
  DesignComparisonOptions comparison;
  comparison.budgets = {100};  // below the adaptive start design of 200
  EXPECT_THROW(compare_designs(comparison), std::invalid_argument);
  comparison.budgets = {500, 500};
  EXPECT_THROW(compare_designs(comparison), std::invalid_argument);
}

// The full Fig. 10 study (100 truths per dimension, both fit-data selections) and the adaptive vs
// two-stage comparison are measurements to read, minutes long, not checks: they are the report
// `nibrig space synth --compare [--all-judgments] [--report DIR]`. The tests above check the same
// code on small studies with stated tolerances.

}  // namespace
}  // namespace nibrig::model::space
