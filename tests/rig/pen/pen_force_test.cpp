#include "rig/pen/pen_force.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>
#include <string>

namespace nibrig::rig::pen {
namespace {

// Straight lines between points are exact up to rounding: 1e-12 N.
constexpr double kPenForceExact = 1e-12;

TEST(PressureCurve, InterpolatesBetweenPointsAndIsZeroAtOrBelowTheThreshold) {
  const PressureCurve curve({{0.05, 0.0}, {0.25, 1.0}, {0.65, 3.0}});
  EXPECT_EQ(curve.force_n(0.0), 0.0);
  EXPECT_EQ(curve.force_n(0.05), 0.0);
  EXPECT_EQ(curve.force_n(-0.5), 0.0);
  EXPECT_EQ(curve.force_n(std::numeric_limits<double>::quiet_NaN()), 0.0);
  EXPECT_NEAR(curve.force_n(0.15), 0.5, kPenForceExact);
  EXPECT_NEAR(curve.force_n(0.25), 1.0, kPenForceExact);
  EXPECT_NEAR(curve.force_n(0.45), 2.0, kPenForceExact);
  EXPECT_NEAR(curve.force_n(0.65), 3.0, kPenForceExact);
}

// Above the last point the last segment goes on (5 N per unit of pressure here), to pressure 1.
TEST(PressureCurve, ExtrapolatesTheLastSegmentAboveTheLastPoint) {
  const PressureCurve curve({{0.0, 0.0}, {0.2, 0.4}, {0.6, 2.4}});
  EXPECT_NEAR(curve.force_n(0.8), 3.4, kPenForceExact);
  EXPECT_NEAR(curve.force_n(1.0), 4.4, kPenForceExact);
}

// The default: straight from 0 N to 500 g-force (Huion's stated maximum) at pressure 1.
TEST(PressureCurve, TheDefaultSpansZeroToFiveHundredGramsForce) {
  const PressureCurve& curve = default_pressure_curve();
  EXPECT_NEAR(kDefaultFullScaleN, 4.903325, 1e-9);
  EXPECT_EQ(curve.force_n(0.0), 0.0);
  EXPECT_NEAR(curve.force_n(1.0), 4.903325, kPenForceExact);
  EXPECT_NEAR(curve.force_n(0.5), 4.903325 / 2, kPenForceExact);
}

void expect_pen_curve_refused(std::vector<PressurePoint> points, const std::string& part) {
  try {
    PressureCurve curve(std::move(points));
    ADD_FAILURE() << "accepted; expected a refusal saying: " << part;
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find(part), std::string::npos) << error.what();
  }
}

TEST(PressureCurve, RefusesPointsThatAreNotAMonotoneCurve) {
  expect_pen_curve_refused({{0.0, 0.0}}, "at least two points");
  expect_pen_curve_refused({{0.1, 0.5}, {0.5, 2.0}}, "point 0: expected the first point at 0 N");
  expect_pen_curve_refused({{0.0, 0.0}, {0.5, 2.0}, {0.4, 3.0}},
                           "point 2: expected pressures rising");
  expect_pen_curve_refused({{0.0, 0.0}, {0.5, 2.0}, {0.6, 2.0}}, "point 2: expected forces rising");
  expect_pen_curve_refused({{0.0, 0.0}, {1.5, 2.0}}, "point 1: expected a pressure from 0 to 1");
  expect_pen_curve_refused({{0.0, 0.0}, {0.5, 80.0}}, "point 1: expected a force from 0 to 50 N");
}

}  // namespace
}  // namespace nibrig::rig::pen
