#include "model/space/cross_validation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "tests/model/space/study_fixture.hpp"

namespace nibrig::model::space {
namespace {

TEST(SpaceCrossValidation, FoldsAreBalancedAndSeeded) {
  const std::vector<int> f = assign_folds(103, 5, 7);
  std::vector<int> size(5, 0);
  for (int k : f) ++size[static_cast<std::size_t>(k)];
  EXPECT_EQ(*std::max_element(size.begin(), size.end()) - *std::min_element(size.begin(), size.end()),
            1);  // 103 = 5·20 + 3
  EXPECT_EQ(f, assign_folds(103, 5, 7));
  EXPECT_NE(f, assign_folds(103, 5, 8));
  EXPECT_THROW(assign_folds(3, 5, 1), std::invalid_argument);
  EXPECT_THROW(assign_folds(10, 1, 1), std::invalid_argument);
}

TEST(SpaceCrossValidation, HeldOutErrorApproachesTheObserversOwnNoise) {
  // 10 stimuli in 2-D, every triplet judged 10 times. The held-out error cannot go below the
  // binomial noise of the observed proportions, E|p̂ − p| ≈ √(2p(1−p)/(π·10)) ≈ 0.10-0.12 for these
  // p; a space recovered from 4/5 of the data should add little to that, and far less than the
  // error of predicting 0.5 everywhere.
  const Eigen::MatrixXd truth = testing::random_truth(2, 10, 21);
  const SpaceProblem study = testing::every_triplet_judged(truth, 10, 5);
  CrossValidationOptions options;
  options.fit.starts = 4;
  const CrossValidationResult cv = cross_validate(study, options);
  ASSERT_EQ(cv.folds.size(), 5u);
  std::vector<double> truth_p = predict_triplets(truth, study.triplets, study.model);
  const PredictionScores floor = score_predictions(truth_p, study.triplets);
  const PredictionScores chance =
      score_predictions(std::vector<double>(study.triplets.size(), 0.5), study.triplets);
  EXPECT_LT(cv.pooled.mean_absolute_error, floor.mean_absolute_error + 0.02);  // +2 points
  EXPECT_LT(cv.pooled.mean_absolute_error, 0.6 * chance.mean_absolute_error);
  EXPECT_GT(cv.pooled.majority.fraction, 0.85);  // the truth itself agrees ~0.9 of the time
  EXPECT_NEAR(cv.mean_fold_error, cv.pooled.mean_absolute_error, 0.01);  // equal-size folds
  for (const auto& f : cv.folds) EXPECT_EQ(f.unseen_stimulus_triplets, 0u);
}

}  // namespace
}  // namespace nibrig::model::space
