#include "model/space/bootstrap.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>

#include "model/space/fit.hpp"
#include "tests/model/space/study_fixture.hpp"

namespace nibrig::model::space {
namespace {

double mean_major_axis(const BootstrapResult& b, std::size_t level) {
  double sum = 0.0;
  for (const auto& r : b.regions) sum += plane_ellipse(r, level).semi_axis_1;
  return sum / static_cast<double>(b.regions.size());
}

TEST(SpaceBootstrap, RegionsEncloseTheirLevelAndShrinkWithMoreJudgments) {
  const Eigen::MatrixXd truth = testing::random_truth(2, 8, 31);
  BootstrapOptions options;
  options.resamples = 200;
  options.threads = 2;
  auto regions_for = [&](int judgments) {
    const SpaceProblem study = testing::every_triplet_judged(truth, judgments, 9);
    FitOptions fit_options;
    fit_options.starts = 4;
    const FitResult reference = fit_space(study, fit_options);
    return bootstrap_space(study, reference.coordinates, options);
  };
  const BootstrapResult few = regions_for(4), many = regions_for(16);
  ASSERT_EQ(few.regions.size(), 8u);
  ASSERT_EQ(few.aligned.size(), 200u);
  // By construction each region holds its level of the cloud: count it independently.
  for (std::size_t s = 0; s < few.regions.size(); ++s) {
    const auto& r = few.regions[s];
    const Eigen::MatrixXd inverse = r.covariance.inverse();
    int inside = 0;
    for (const auto& a : few.aligned) {
      const Eigen::VectorXd d = a.col(static_cast<Eigen::Index>(s)) - r.mean;
      inside += std::sqrt(d.dot(inverse * d)) <= r.radius[0] * (1 + 1e-6);  // the region inverts a covariance regularised by 1e-9 of its trace
    }
    EXPECT_GE(inside, 136) << "stimulus " << s;  // ⌈0.68·200⌉
    EXPECT_LE(inside, 140) << "stimulus " << s;  // ties at the quantile add at most a few
    EXPECT_LT(r.radius[0], r.radius[1]);
  }
  // Four times the judgments: the spread of a maximum-likelihood estimate shrinks as 1/√N, so the
  // ellipses halve; ±25 % for the bootstrap's own sampling error with 200 resamples.
  const double ratio = mean_major_axis(many, 1) / mean_major_axis(few, 1);
  EXPECT_NEAR(ratio, 0.5, 0.125);
}

TEST(SpaceBootstrap, PlaneEllipseOfADiagonalCovariance) {
  ConfidenceRegion r;
  r.mean = Eigen::Vector2d(0, 0);
  r.covariance = Eigen::Matrix2d{{1.0, 0.0}, {0.0, 4.0}};
  r.radius = {2.0};
  const PlaneEllipse e = plane_ellipse(r, 0);
  EXPECT_NEAR(e.semi_axis_1, 4.0, 1e-12);  // 2·√4 along y
  EXPECT_NEAR(e.semi_axis_2, 2.0, 1e-12);
  EXPECT_NEAR(std::abs(std::cos(e.angle_rad)), 0.0, 1e-12);
}

TEST(SpaceBootstrap, MeanPerAxisSdOfHandMadeRegions) {
  // sd per axis sqrt(trace / dims): sqrt((0.04 + 0.16) / 2) = sqrt(0.1) and sqrt(2 / 2) = 1.
  BootstrapResult result;
  result.regions.resize(2);
  result.regions[0].covariance = Eigen::Matrix2d{{0.04, 0.0}, {0.0, 0.16}};
  result.regions[1].covariance = Eigen::Matrix2d{{1.0, 0.3}, {0.3, 1.0}};
  EXPECT_NEAR(mean_per_axis_sd(result), 0.5 * (std::sqrt(0.1) + 1.0), 1e-15);
  EXPECT_EQ(mean_per_axis_sd(BootstrapResult{}), 0.0);
}

TEST(SpaceBootstrap, AGaussianPlacementsRegionHasTheChiSquaredRadius) {
  // With 2 degrees of freedom the χ² quantile has a closed form, -2 ln(1 - p).
  const ConfidenceRegion r =
      gaussian_region(Eigen::Vector2d(1, 2), Eigen::Matrix2d{{0.25, 0.0}, {0.0, 1.0}}, {0.68, 0.95});
  ASSERT_EQ(r.radius.size(), 2u);
  EXPECT_NEAR(r.radius[0], std::sqrt(-2 * std::log(1 - 0.68)), 1e-9);
  EXPECT_NEAR(r.radius[1], std::sqrt(-2 * std::log(1 - 0.95)), 1e-9);
  EXPECT_NEAR(plane_ellipse(r, 1).semi_axis_1, r.radius[1] * 1.0, 1e-12);  // along y, sd 1
  EXPECT_NEAR(plane_ellipse(r, 1).semi_axis_2, r.radius[1] * 0.5, 1e-12);
  // In one dimension the 95 % interval is ±1.96 sd: a flat ellipse along the axis.
  const ConfidenceRegion line = gaussian_region(Eigen::VectorXd::Constant(1, 0.0),
                                                Eigen::MatrixXd::Constant(1, 1, 4.0), {0.95});
  const PlaneEllipse e = plane_ellipse(line, 0);
  EXPECT_NEAR(e.semi_axis_1, 1.959964 * 2.0, 1e-5);
  EXPECT_EQ(e.semi_axis_2, 0.0);
}

TEST(SpaceBootstrap, RejectsBadOptions) {
  const SpaceProblem study = testing::every_triplet_judged(testing::random_truth(2, 5, 1), 2, 1);
  const Eigen::MatrixXd reference = Eigen::MatrixXd::Zero(2, 5);
  BootstrapOptions o;
  o.resamples = 1;
  EXPECT_THROW(bootstrap_space(study, reference, o), std::invalid_argument);
  o.resamples = 4;
  o.levels = {1.0};
  EXPECT_THROW(bootstrap_space(study, reference, o), std::invalid_argument);
  o.levels = {0.5};
  EXPECT_THROW(bootstrap_space(study, Eigen::MatrixXd::Zero(3, 5), o), std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::model::space
