#include "model/space/descriptor_map.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <random>

namespace nibrig::model::space {
namespace {

// n stimuli with 2 descriptors and a 2-D space that is a linear function of them plus noise.
struct LinearWorld {
  Eigen::MatrixXd descriptors, coordinates, map;
  Eigen::VectorXd offset;
};

LinearWorld linear_world(Eigen::Index n, double noise, std::mt19937_64& generator) {
  std::normal_distribution<double> normal(0.0, 1.0);
  LinearWorld w;
  w.map = Eigen::Matrix2d{{2.0, 0.5}, {-1.0, 3.0}};
  w.offset = Eigen::Vector2d(0.3, -0.7);
  w.descriptors.resize(n, 2);
  w.coordinates.resize(2, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    w.descriptors.row(i) << normal(generator), 0.1 * normal(generator) + 1.0;
    w.coordinates.col(i) = w.offset + w.map * w.descriptors.row(i).transpose() +
                           noise * Eigen::Vector2d(normal(generator), normal(generator));
  }
  return w;
}

TEST(SpaceDescriptorMap, ExactlyLinearDataIsReproduced) {
  std::mt19937_64 generator(1);
  const LinearWorld w = linear_world(12, 0.0, generator);
  const DescriptorMap m = fit_descriptor_map(w.coordinates, w.descriptors, {"x", "y"});
  const Eigen::Vector2d x(0.4, 1.2);
  const Placement p = place_from_descriptors(m, x);
  EXPECT_TRUE(p.mean.isApprox(w.offset + w.map * x, 1e-10));
  EXPECT_LT(p.covariance.norm(), 1e-20);  // no residual: no uncertainty
  EXPECT_NEAR(m.r_squared[0], 1.0, 1e-12);
}

TEST(SpaceDescriptorMap, PredictionRegionsCoverNewToolsAtTheirLevel) {
  // Monte Carlo against the regression's own theory: a new tool drawn from the same world falls
  // inside the Mahalanobis radius √χ²₂(0.68) = 1.510 of its placement about 68 % of the time (a
  // little less: the covariance is estimated from 15 stimuli, so the exact law is Hotelling's T²);
  // 2000 worlds give a sampling error of ±1 point.
  std::mt19937_64 generator(3);
  int inside = 0;
  const int worlds = 2000;
  for (int k = 0; k < worlds; ++k) {
    const LinearWorld w = linear_world(16, 0.2, generator);
    const DescriptorMap m =
        fit_descriptor_map(w.coordinates.leftCols(15), w.descriptors.topRows(15), {"x", "y"});
    const Placement p = place_from_descriptors(m, w.descriptors.row(15).transpose());
    const Eigen::Vector2d d = w.coordinates.col(15) - p.mean;
    inside += d.dot(p.covariance.inverse() * d) <= 1.510 * 1.510;
  }
  const double coverage = static_cast<double>(inside) / worlds;
  EXPECT_GT(coverage, 0.60);  // T² with 12 residual degrees: ≈ 0.63-0.65
  EXPECT_LT(coverage, 0.70);
}

TEST(SpaceDescriptorMap, UncertainProbabilityIsExactForCertainPositions) {
  Placement r{Eigen::Vector2d(0, 0), Eigen::Matrix2d::Zero()};
  Placement a{Eigen::Vector2d(1, 0), Eigen::Matrix2d::Zero()};
  Placement b{Eigen::Vector2d(0, 2), Eigen::Matrix2d::Zero()};
  std::mt19937_64 generator(1);
  const UncertainProbability u = uncertain_probability_first(r, a, b, JudgmentModel{}, 50, generator);
  EXPECT_NEAR(u.mean, 0.5 * std::erfc(-(2.0 / 3.0) / std::sqrt(2.0)), 1e-12);  // Φ(2/3)
  EXPECT_NEAR(u.sd, 0.0, 1e-12);
  b.covariance = Eigen::Matrix2d::Identity();
  EXPECT_GT(uncertain_probability_first(r, a, b, JudgmentModel{}, 200, generator).sd, 0.01);
}

TEST(SpaceDescriptorMap, RejectsTablesThatDoNotMatch) {
  const Eigen::MatrixXd q = Eigen::MatrixXd::Random(2, 5);
  EXPECT_THROW(fit_descriptor_map(q, Eigen::MatrixXd::Random(4, 2), {"x", "y"}),
               std::invalid_argument);  // rows ≠ stimuli
  EXPECT_THROW(fit_descriptor_map(q, Eigen::MatrixXd::Random(5, 2), {"x"}), std::invalid_argument);
  EXPECT_THROW(fit_descriptor_map(q.leftCols(3), Eigen::MatrixXd::Random(3, 2), {"x", "y"}),
               std::invalid_argument);  // no residual degree of freedom
  Eigen::MatrixXd constant = Eigen::MatrixXd::Random(5, 2);
  constant.col(1).setConstant(1.0);
  EXPECT_THROW(fit_descriptor_map(q, constant, {"x", "y"}), std::invalid_argument);
  const DescriptorMap m = fit_descriptor_map(q, Eigen::MatrixXd::Random(5, 2), {"x", "y"});
  EXPECT_THROW(place_from_descriptors(m, Eigen::VectorXd::Zero(3)), std::invalid_argument);
}

TEST(SpaceDescriptorMap, UncertainDescriptorsAddTheirErrorCarriedThroughTheMap) {
  // The reference: the map's Jacobian by central differences of the placed means (not from its
  // coefficients and scales), and J·Σ·Jᵀ added to the covariance of the certain placement. The
  // map is linear, so the differences are exact up to rounding.
  std::mt19937_64 generator(11);
  const LinearWorld w = linear_world(20, 0.3, generator);
  const DescriptorMap m = fit_descriptor_map(w.coordinates, w.descriptors, {"x", "y"});
  const Eigen::Vector2d x(0.2, 1.05);
  Eigen::Matrix2d jacobian;
  for (Eigen::Index j = 0; j < 2; ++j) {
    Eigen::Vector2d step = Eigen::Vector2d::Zero();
    step(j) = 1e-3;
    jacobian.col(j) =
        (place_from_descriptors(m, x + step).mean - place_from_descriptors(m, x - step).mean) /
        2e-3;
  }
  const Eigen::Matrix2d sigma{{0.04, 0.01}, {0.01, 0.0025}};
  const Placement certain = place_from_descriptors(m, x);
  const Placement uncertain = place_from_descriptors(m, x, sigma);
  EXPECT_TRUE(uncertain.mean.isApprox(certain.mean, 1e-15));
  const Eigen::Matrix2d expected = certain.covariance + jacobian * sigma * jacobian.transpose();
  EXPECT_TRUE(uncertain.covariance.isApprox(expected, 1e-8)) << uncertain.covariance << "\n"
                                                             << expected;
  // A zero error changes nothing.
  EXPECT_TRUE(place_from_descriptors(m, x, Eigen::Matrix2d::Zero())
                  .covariance.isApprox(certain.covariance, 1e-15));
  // Bad covariances are refused: wrong size, a negative variance, not symmetric.
  EXPECT_THROW(place_from_descriptors(m, x, Eigen::Matrix3d::Identity()), std::invalid_argument);
  EXPECT_THROW(place_from_descriptors(m, x, Eigen::Matrix2d{{-0.1, 0}, {0, 0.1}}),
               std::invalid_argument);
  EXPECT_THROW(place_from_descriptors(m, x, Eigen::Matrix2d{{0.1, 0.05}, {0.0, 0.1}}),
               std::invalid_argument);
}

TEST(SpaceDescriptorMap, UncertainDistanceMatchesTheClosedFormOfAHalfNormal) {
  std::mt19937_64 generator(7);
  // Certain positions: the distance itself, no spread.
  const Placement a{Eigen::Vector2d(0, 0), Eigen::Matrix2d::Zero()};
  const Placement b{Eigen::Vector2d(3, 4), Eigen::Matrix2d::Zero()};
  const auto certain = uncertain_distance(a, b, 100, generator);
  EXPECT_DOUBLE_EQ(certain.between_means, 5.0);
  EXPECT_NEAR(certain.sd, 0.0, 1e-12);
  // One dimension, equal means, each N(0, σ²): |X − Y| is half-normal with scale σ√2, whose sd is
  // σ√2·√(1 − 2/π). 40,000 draws: the sd's relative standard error is ~0.5 %; 3 % is ample.
  const double sigma = 0.3;
  const Placement x{Eigen::VectorXd::Zero(1), Eigen::MatrixXd::Constant(1, 1, sigma * sigma)};
  const auto spread = uncertain_distance(x, x, 40000, generator);
  EXPECT_DOUBLE_EQ(spread.between_means, 0.0);
  const double expected = sigma * std::sqrt(2.0) * std::sqrt(1 - 2 / M_PI);
  EXPECT_NEAR(spread.sd, expected, 0.03 * expected);
  EXPECT_THROW(uncertain_distance(a, x, 100, generator), std::invalid_argument);
}

TEST(SpaceDescriptorMap, AGroupDistanceIsTheLargestOrMeanOverJointDraws) {
  std::mt19937_64 generator(11);
  const Placement a{Eigen::Vector2d(0, 0), Eigen::Matrix2d::Zero()};
  const Placement near{Eigen::Vector2d(3, 4), Eigen::Matrix2d::Zero()};
  const Placement far{Eigen::Vector2d(-6, 8), Eigen::Matrix2d::Zero()};
  // Certain positions: 5 and 10 exactly; the largest 10, the mean 7.5, no spread.
  const auto largest = uncertain_group_distance(a, {near, far}, GroupAim::largest, 100, generator);
  EXPECT_DOUBLE_EQ(largest.aggregate.between_means, 10.0);
  EXPECT_NEAR(largest.aggregate.sd, 0.0, 1e-12);
  ASSERT_EQ(largest.each.size(), 2u);
  EXPECT_DOUBLE_EQ(largest.each[0].between_means, 5.0);
  EXPECT_DOUBLE_EQ(largest.each[1].between_means, 10.0);
  EXPECT_DOUBLE_EQ(uncertain_group_distance(a, {near, far}, GroupAim::mean, 100, generator).aggregate.between_means, 7.5);

  // The design uncertain (σ = 0.1 on each axis), two targets 10 away on either side along x: each
  // distance varies as the design's x, by σ (first order; the curvature adds σ²/20), but their
  // mean is 10 + y²/20 whatever x is, so its sd is σ²·√2/20 = 7e-4 — only if the design's draw is
  // shared by both distances. 20,000 draws: the sds' relative standard error is 0.5 %.
  const double sigma = 0.1;
  const Placement design{Eigen::Vector2d(0, 0), Eigen::Matrix2d::Identity() * sigma * sigma};
  const Placement left{Eigen::Vector2d(-10, 0), Eigen::Matrix2d::Zero()};
  const Placement right{Eigen::Vector2d(10, 0), Eigen::Matrix2d::Zero()};
  const auto mean = uncertain_group_distance(design, {left, right}, GroupAim::mean, 20000, generator);
  EXPECT_NEAR(mean.each[0].sd, sigma, 0.03 * sigma);
  EXPECT_NEAR(mean.each[1].sd, sigma, 0.03 * sigma);
  EXPECT_LT(mean.aggregate.sd, 0.002);
  // The largest of the two is 10 + |x|: a half-normal's sd, σ·√(1 − 2/π).
  const auto most = uncertain_group_distance(design, {left, right}, GroupAim::largest, 20000, generator);
  const double half_normal = sigma * std::sqrt(1 - 2 / M_PI);
  EXPECT_NEAR(most.aggregate.sd, half_normal, 0.03 * half_normal + 0.001);  // + the curvature's
  EXPECT_THROW(uncertain_group_distance(a, {}, GroupAim::mean, 100, generator), std::invalid_argument);
  const Placement one_d{Eigen::VectorXd::Zero(1), Eigen::MatrixXd::Zero(1, 1)};
  EXPECT_THROW(uncertain_group_distance(a, {near, one_d}, GroupAim::mean, 100, generator), std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::model::space
