// The Hermite scaling curves: exact on straight lines, through their knots, C1 at the knots with
// the finite-difference tangents they promise.
#include "model/forcing/hermite_curve.hpp"

#include <gtest/gtest.h>

#include <random>

namespace nibrig::model::forcing {
namespace {

std::vector<double> random_values(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  std::vector<double> v(n);
  for (double& x : v) x = u(rng);
  return v;
}

TEST(HermiteCurve, DefaultKnotsAreThePapersElevenEvery50Hz) {
  const auto knots = default_knot_frequencies();
  ASSERT_EQ(knots.size(), 11u);
  for (std::size_t k = 0; k < knots.size(); ++k) EXPECT_DOUBLE_EQ(knots[k], 50.0 * k);
}

TEST(HermiteCurve, ReproducesAStraightLineExactly) {
  // Uniform and uneven knots: one-sided and central differences are both exact on a line.
  for (const std::vector<double>& knots :
       {default_knot_frequencies(), std::vector<double>{0, 7, 30, 31, 90, 200}}) {
    std::vector<double> values;
    for (double x : knots) values.push_back(0.3 - 0.0125 * x);
    for (double x = knots.front(); x <= knots.back(); x += 0.37)
      EXPECT_NEAR(hermite_value(knots, values, x), 0.3 - 0.0125 * x, 1e-12) << "x = " << x;
  }
}

TEST(HermiteCurve, InterpolatesTheKnotsAndItsWeightsSumToOne) {
  const auto knots = default_knot_frequencies();
  const auto values = random_values(knots.size(), 3);
  for (std::size_t k = 0; k < knots.size(); ++k)
    EXPECT_NEAR(hermite_value(knots, values, knots[k]), values[k], 1e-14);
  for (double x = 0; x <= 500; x += 3.3) {
    const auto weights = hermite_weights(knots, x);
    EXPECT_LE(weights.size(), 4u);  // two knots of the interval and their outer neighbours
    double sum = 0;
    for (const auto& [k, w] : weights) sum += w;
    EXPECT_NEAR(sum, 1.0, 1e-14) << "constants must be reproduced, x = " << x;
  }
}

TEST(HermiteCurve, IsC1AtTheKnotsWithFiniteDifferenceTangents) {
  const std::vector<double> knots{0, 50, 100, 180, 250, 400, 500};
  const auto values = random_values(knots.size(), 11);
  const double h = 1e-6;
  for (std::size_t k = 0; k < knots.size(); ++k) {
    // The tangent the curve promises, written out independently: central inside, one-sided at
    // the ends.
    const std::size_t lo = k == 0 ? 0 : k - 1, hi = k + 1 == knots.size() ? k : k + 1;
    const double tangent = (values[hi] - values[lo]) / (knots[hi] - knots[lo]);
    // One-sided difference quotients from each side; O(h) error with second derivatives O(1e-3).
    if (k > 0) {
      const double left = (values[k] - hermite_value(knots, values, knots[k] - h)) / h;
      EXPECT_NEAR(left, tangent, 1e-6) << "left of knot " << k;
    }
    if (k + 1 < knots.size()) {
      const double right = (hermite_value(knots, values, knots[k] + h) - values[k]) / h;
      EXPECT_NEAR(right, tangent, 1e-6) << "right of knot " << k;
    }
  }
}

TEST(HermiteCurve, RefusesToExtrapolateAndBadKnots) {
  const auto knots = default_knot_frequencies();
  EXPECT_THROW(hermite_weights(knots, -0.1), std::invalid_argument);
  EXPECT_THROW(hermite_weights(knots, 500.1), std::invalid_argument);
  EXPECT_NO_THROW(hermite_weights(knots, 500.0));
  EXPECT_THROW(hermite_weights(std::vector<double>{1.0}, 1.0), std::invalid_argument);
  EXPECT_THROW(hermite_weights(std::vector<double>{0, 2, 2, 3}, 1.0), std::invalid_argument);
  EXPECT_THROW(hermite_value(knots, std::vector<double>(10, 0.0), 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::model::forcing
