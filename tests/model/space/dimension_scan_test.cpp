#include "model/space/dimension_scan.hpp"

#include <gtest/gtest.h>

#include "tests/model/space/study_fixture.hpp"

namespace nibrig::model::space {
namespace {

TEST(SpaceDimensionScan, ATwoDimensionalTruthIsBestExplainedInTwoOrMoreDimensions) {
  // Fig. 8's shape: a clear gain from 1 to 2 dimensions, little beyond. A 2-D truth whose second
  // axis spans as much as its first cannot be predicted well along one line (measured: 0.135 in
  // 1-D against 0.080 in 2-D and 3-D, about the noise floor of 20 judgments per triplet).
  const Eigen::MatrixXd truth = testing::random_truth(2, 12, 44);
  const SpaceProblem study = testing::every_triplet_judged(truth, 20, 2);
  DimensionScanOptions options;
  options.dims = {1, 2, 3};
  options.cross_validation.fit.starts = 4;
  const std::vector<DimensionScanPoint> scan = scan_dimensions(study, nullptr, options);
  ASSERT_EQ(scan.size(), 3u);
  EXPECT_LT(scan[1].mean_error, scan[0].mean_error - 0.03);   // 3 points: well above fold noise
  EXPECT_NEAR(scan[2].mean_error, scan[1].mean_error, 0.02);  // a spare axis barely helps
}

TEST(SpaceDimensionScan, LambdaNeedsDescriptors) {
  const SpaceProblem study = testing::every_triplet_judged(testing::random_truth(2, 6, 1), 2, 1);
  DimensionScanOptions options;
  options.lambdas = {1.0};
  EXPECT_THROW(scan_dimensions(study, nullptr, options), std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::model::space
