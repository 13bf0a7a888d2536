#include "rig/pen/pen_calibration.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "rig/pen/pen_load.hpp"

namespace nibrig::rig::pen {
namespace {

// The pen the tests calibrate: its pressure grows as the load to the power 0.6 up to pressure 1 at
// 4.9 N (steeper at light loads, as an EMR pen's does), with a hand's 1 % tremor on each report
// and 8192 pressure levels.
double simulated_pen_pressure(double force_n) {
  return std::min(1.0, std::pow(force_n / 4.9, 0.6));
}

class PenOnAScale {
 public:
  explicit PenOnAScale(PenCalibrator& calibrator) : calibrator_(calibrator) {}

  // Reports at 133 Hz for `seconds`, the pressure going from where it was to `pressure` over
  // `ramp_s` and then held there (tremor added).
  void press(double pressure, double seconds, double ramp_s = 0.0, double tremor = 0.01) {
    const double from = pressure_;
    const double end = now_ + seconds;
    while (now_ + kPeriod <= end + 1e-12) {
      now_ += kPeriod;
      const double ramp = ramp_s > 0.0 ? std::min(1.0, (now_ - (end - seconds)) / ramp_s) : 1.0;
      const double target = from + (pressure - from) * ramp;
      PenSample s;
      s.time_s = now_;
      s.x_m = 0.05;
      s.y_m = 0.04;
      s.pressure = std::clamp(
          std::round(target * (1.0 + tremor * noise_(random_)) * 8191.0) / 8191.0, 0.0, 1.0);
      s.tip_down = true;
      s.in_proximity = true;
      calibrator_.add(s);
    }
    pressure_ = pressure;
  }
  void lift() {
    now_ += kPeriod;
    PenSample s;
    s.time_s = now_;
    s.in_proximity = true;
    calibrator_.add(s);
    pressure_ = 0.0;
  }
  void wait(double seconds) { now_ += seconds; }
  double now() const { return now_; }

  static constexpr double kPeriod = 1.0 / 133.0;

 private:
  PenCalibrator& calibrator_;
  double now_ = 1000.0;
  double pressure_ = 0.0;
  std::mt19937 random_{7};
  std::normal_distribution<double> noise_{0.0, 1.0};
};

const std::vector<double> kPenTestLoads = {0.05 * kStandardGravity, 0.15 * kStandardGravity,
                                           0.30 * kStandardGravity, 0.45 * kStandardGravity};

// Four holds on one press (a ramp between loads, each then held 0.8 s) recover the pen: at each
// load the curve gives the load back, and between loads the straight line between the pen's true
// points. Tolerance 1 %: the 1 % tremor averaged over the window's ~66 reports leaves 0.12 % on the
// pressure, which the curve's slope turns into at most 0.2 % of the force (p ∝ F^0.6), so 1 % is
// five standard deviations; 8192 levels add under 0.05 %.
TEST(PenCalibration, FourHoldsRecoverAKnownCurve) {
  PenCalibrator calibrator;
  PenOnAScale pen(calibrator);
  for (const double load : kPenTestLoads) {
    pen.press(simulated_pen_pressure(load), 0.4, 0.3);
    EXPECT_FALSE(calibrator.check(pen.now()).ready) << "the window still holds the ramp";
    pen.press(simulated_pen_pressure(load), 0.7);
    const PenHoldCheck settled = calibrator.check(pen.now());
    EXPECT_TRUE(settled.ready) << settled.problem;
    const PenHold h = calibrator.hold(load, pen.now());
    EXPECT_NEAR(h.pressure, simulated_pen_pressure(load), 0.005 * simulated_pen_pressure(load));
    EXPECT_GE(h.samples, 60u);  // 0.5 s at 133 Hz: 66 or 67 reports
  }
  const PressureCurve curve = calibrator.fit();
  ASSERT_EQ(curve.points().size(), kPenTestLoads.size() + 1);
  EXPECT_EQ(curve.points()[0].pressure, 0.0);
  for (const double load : kPenTestLoads)
    EXPECT_NEAR(curve.force_n(simulated_pen_pressure(load)), load, 0.01 * load);
  const double between = 2.2;  // between 150 g and 300 g
  const double p1 = simulated_pen_pressure(kPenTestLoads[1]),
               p2 = simulated_pen_pressure(kPenTestLoads[2]);
  const double p = simulated_pen_pressure(between);
  const double straight =
      kPenTestLoads[1] + (p - p1) / (p2 - p1) * (kPenTestLoads[2] - kPenTestLoads[1]);
  EXPECT_NEAR(curve.force_n(p), straight, 0.01 * straight);
}

void expect_pen_hold_refused(PenCalibrator& calibrator, double load, double now,
                             const std::string& part) {
  try {
    calibrator.hold(load, now);
    ADD_FAILURE() << "hold accepted; expected a refusal saying: " << part;
  } catch (const PenCalibrationRefusal& refusal) {
    EXPECT_NE(std::string(refusal.what()).find(part), std::string::npos) << refusal.what();
  }
}

TEST(PenCalibration, AHoldIsRefusedWhenTheTipIsUpTooShortTooSparseOrNotSteady) {
  PenCalibrator calibrator;
  PenOnAScale pen(calibrator);
  expect_pen_hold_refused(calibrator, 1.0, pen.now(),
                          "load 1 N (102 g) not taken: the pen's tip is up");
  pen.press(0.4, 1.0);
  pen.lift();
  expect_pen_hold_refused(calibrator, 1.0, pen.now(), "tip is up");

  pen.press(0.4, 0.3);
  expect_pen_hold_refused(calibrator, 1.0, pen.now(), "hold the load for at least 0.50 s");
  pen.lift();

  // A pen that sends three reports in a second (libinput sends changes only).
  pen.press(0.4, 3 * PenOnAScale::kPeriod);
  pen.wait(1.0);
  expect_pen_hold_refused(calibrator, 1.0, pen.now(),
                          "sent 3 reports since its tip went down, expected at least 5");
  pen.lift();

  // Pressing on through the window: from 0.30 to 0.45 over its 0.5 s, a spread of 11 % of the mean.
  pen.press(0.30, 1.0, 0.0, 0.0);
  pen.press(0.45, 0.5, 0.5, 0.0);
  expect_pen_hold_refused(calibrator, 1.0, pen.now(), "not steady");
  pen.lift();

  pen.press(0.0, 1.0, 0.0, 0.0);
  expect_pen_hold_refused(calibrator, 1.0, pen.now(), "no pressure");
  EXPECT_THROW(calibrator.hold(-1.0, pen.now()), std::invalid_argument);
  EXPECT_THROW(calibrator.hold(200.0, pen.now()), std::invalid_argument);
  EXPECT_TRUE(calibrator.holds().empty());
}

void expect_pen_fit_refused(const PenCalibrator& calibrator, const std::string& part) {
  try {
    calibrator.fit();
    ADD_FAILURE() << "fit accepted; expected a refusal saying: " << part;
  } catch (const PenCalibrationRefusal& refusal) {
    EXPECT_NE(std::string(refusal.what()).find(part), std::string::npos) << refusal.what();
  }
}

TEST(PenCalibration, AFitNeedsThreeLoadsWithPressuresRisingWithLoad) {
  PenCalibrator calibrator;
  PenOnAScale pen(calibrator);
  pen.press(0.25, 1.0);
  calibrator.hold(0.49, pen.now());
  pen.press(0.45, 1.0, 0.2);
  calibrator.hold(1.47, pen.now());
  expect_pen_fit_refused(calibrator, "at least 3 different loads, held 2");
  // The same load again is averaged in, not a third load.
  pen.press(0.45, 1.0);
  calibrator.hold(1.475, pen.now());
  expect_pen_fit_refused(calibrator, "held 2");
  // A heavier load with less pressure: named.
  pen.press(0.40, 1.0, 0.2);
  calibrator.hold(2.94, pen.now());
  expect_pen_fit_refused(calibrator, "the pressure under 2.94 N (300 g)");
  calibrator.forget_last_hold();
  pen.press(0.70, 1.0, 0.2);
  calibrator.hold(2.94, pen.now());
  const PressureCurve curve = calibrator.fit();
  EXPECT_EQ(curve.points().size(), 4u);
}

// Loads as typed: grams from a kitchen scale (standard gravity), newtons from the rig's sensor.
TEST(PenCalibration, LoadsAreReadInGramsOrNewtons) {
  EXPECT_NEAR(parse_pen_load("200g"), 1.96133, 1e-12);
  EXPECT_NEAR(parse_pen_load(" 200 g "), 1.96133, 1e-12);
  EXPECT_NEAR(parse_pen_load("0.2kg"), 1.96133, 1e-12);
  EXPECT_NEAR(parse_pen_load("1.5N"), 1.5, 1e-15);
  EXPECT_NEAR(parse_pen_load("1500 mN"), 1.5, 1e-12);
  for (const std::string bad :
       {"200", "-5g", "0g", "abc", "5 lb", "100kg", "0x10g", "nan g", "inf N", "", "+3N"}) {
    try {
      parse_pen_load(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const std::invalid_argument& error) {
      EXPECT_NE(std::string(error.what()).find("load '" + bad + "'"), std::string::npos)
          << error.what();
    }
  }
}

}  // namespace
}  // namespace nibrig::rig::pen
