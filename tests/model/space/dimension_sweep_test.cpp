#include "model/space/dimension_sweep.hpp"

#include <gtest/gtest.h>

#include "tests/model/space/study_fixture.hpp"

namespace nibrig::model::space {
namespace {

TEST(SpaceDimensionSweep, ATwoDimensionalTruthIsBestExplainedInTwoOrMoreDimensions) {
  // Fig. 8's shape: a clear gain from 1 to 2 dimensions, little beyond. A 2-D truth whose second
  // axis spans as much as its first cannot be predicted well along one line (measured: 0.135 in
  // 1-D against 0.080 in 2-D and 3-D, about the noise floor of 20 judgments per triplet).
  const Eigen::MatrixXd truth = testing::random_truth(2, 12, 44);
  const SpaceProblem study = testing::every_triplet_judged(truth, 20, 2);
  SweepOptions options;
  options.dims = {1, 2, 3};
  options.cross_validation.fit.starts = 4;
  const std::vector<SweepPoint> sweep = sweep_dimensions(study, nullptr, options);
  ASSERT_EQ(sweep.size(), 3u);
  EXPECT_LT(sweep[1].mean_error, sweep[0].mean_error - 0.03);  // 3 points: well above fold noise
  EXPECT_NEAR(sweep[2].mean_error, sweep[1].mean_error, 0.02);  // a spare axis barely helps
}

TEST(SpaceDimensionSweep, LambdaNeedsDescriptors) {
  const SpaceProblem study = testing::every_triplet_judged(testing::random_truth(2, 6, 1), 2, 1);
  SweepOptions options;
  options.lambdas = {1.0};
  EXPECT_THROW(sweep_dimensions(study, nullptr, options), std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::model::space
