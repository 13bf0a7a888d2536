#include "rig/pen/pen_speed.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "tests/rig/pen/pen_speed_synthetic_stroke.hpp"

namespace nibrig::rig::pen {
namespace {

using testing::SyntheticReport;
using testing::TabletModel;
using testing::PenSpeedBounds;
using testing::pen_speed_bounds;

// The mean over n estimates is far closer: the first-order jitter and rounding terms of successive
// differences cancel but for the stroke's ends (4 stamps, 4 positions); the jitter's second-order
// term, at most (2·jitter / 2T)² of the speed, does not; a chord falls short by (1 − chord).
double pen_speed_mean_tolerance(double speed, const TabletModel& tablet, std::size_t n,
                                double chord = 1.0) {
  const double span = 2.0 / tablet.rate_hz;
  const double position = std::sqrt(2.0) * tablet.resolution_m / 2.0;
  const double ends =
      (speed * 4.0 * tablet.jitter_s + 4.0 * position) / span / static_cast<double>(n);
  const double second = speed * std::pow(2.0 * tablet.jitter_s / span, 2.0);
  return ends + second + (1.0 - chord) * speed;
}

struct PenSpeedRun {
  std::vector<double> estimates;  // from the third report on: the first full window
  std::vector<const SyntheticReport*> reports;
};
PenSpeedRun run_pen_speed(PenSpeed& speed, const std::vector<SyntheticReport>& reports) {
  PenSpeedRun run;
  speed.reset();
  for (std::size_t i = 0; i < reports.size(); ++i) {
    const double v =
        speed.add(reports[i].sample.time_s, reports[i].sample.x_m, reports[i].sample.y_m);
    if (i == 0) {
      EXPECT_EQ(v, 0.0) << "the stroke's first report has no speed yet";
    }
    if (i >= 2) {
      run.estimates.push_back(v);
      run.reports.push_back(&reports[i]);
    }
  }
  return run;
}

// 80 mm/s along a line, at the report rates tablets have (100-300 Hz), ±0.5 ms stamp jitter and
// 0.01 mm resolution: every estimate within the bound the tablet's imperfections allow, and the
// stroke's mean close to the path's exact speed.
TEST(PenSpeed, ALineAt80MillimetresPerSecondIsMeasuredWithinTheTabletsImperfections) {
  for (const double rate : {100.0, 133.0, 200.0, 300.0}) {
    SCOPED_TRACE(rate);
    TabletModel tablet;
    tablet.rate_hz = rate;
    const auto reports = testing::synthetic_stroke(testing::straight_line(0.080), 1.5, tablet);
    PenSpeed speed;
    const PenSpeedRun run = run_pen_speed(speed, reports);
    const PenSpeedBounds bounds = pen_speed_bounds(0.080, tablet);
    double sum = 0.0, worst = 0.0;
    for (std::size_t i = 0; i < run.estimates.size(); ++i) {
      EXPECT_GE(run.estimates[i], bounds.low) << "report " << i + 2;
      EXPECT_LE(run.estimates[i], bounds.high) << "report " << i + 2;
      sum += run.estimates[i] - run.reports[i]->true_speed_m_s;
      worst = std::max(worst, std::abs(run.estimates[i] - run.reports[i]->true_speed_m_s));
    }
    const double mean_error = sum / static_cast<double>(run.estimates.size());
    const double mean_tolerance = pen_speed_mean_tolerance(0.080, tablet, run.estimates.size());
    EXPECT_LT(std::abs(mean_error), mean_tolerance);
    std::printf(
        "pen speed at %.0f Hz, 80 mm/s: worst estimate off by %.2f mm/s (bound %.2f to +%.2f), "
        "mean by %+.3f mm/s (tolerance %.3f)\n",
        rate, worst * 1e3, (bounds.low - 0.080) * 1e3, (bounds.high - 0.080) * 1e3,
        mean_error * 1e3, mean_tolerance * 1e3);
    // The median of the intervals: the jitter's difference spreads ±1 ms, and the median of 64 of
    // them lies within 0.25 ms (about four of its standard errors, 0.06 ms).
    EXPECT_NEAR(speed.report_interval_s(), 1.0 / rate, 0.25e-3);
    EXPECT_NEAR(speed.lag_s(), speed.report_interval_s(), 1e-15);
  }
}

// Round a circle (80 mm/s, radius 20 mm, 133 Hz): the same bounds, the chord's shortfall
// included; the reference is the circle's own speed.
TEST(PenSpeed, ACircleIsMeasuredAgainstItsAnalyticSpeed) {
  const TabletModel tablet;
  const double radius = 0.020, v = 0.080;
  const auto reports = testing::synthetic_stroke(testing::circle(v, radius), 2.0, tablet);
  PenSpeed speed;
  const PenSpeedRun run = run_pen_speed(speed, reports);
  const double half_angle = v * (2.0 / tablet.rate_hz) / radius / 2.0;
  const double chord = std::sin(half_angle) / half_angle;
  const PenSpeedBounds bounds = pen_speed_bounds(v, tablet, chord);
  double sum = 0.0;
  for (std::size_t i = 0; i < run.estimates.size(); ++i) {
    EXPECT_GE(run.estimates[i], bounds.low) << "report " << i + 2;
    EXPECT_LE(run.estimates[i], bounds.high) << "report " << i + 2;
    sum += run.estimates[i] - run.reports[i]->true_speed_m_s;
  }
  EXPECT_LT(std::abs(sum / static_cast<double>(run.estimates.size())),
            pen_speed_mean_tolerance(v, tablet, run.estimates.size(), chord));
}

// The lag, measured on a pen speeding up steadily (20 → 270 mm/s at 1 m/s²): how long ago the
// path had the speed each estimate gives. Without jitter it is one report to within the rounding's
// share (0.014 mm over 2T, at 1 m/s²: under 0.94 ms per estimate, far less on the mean); with
// ±0.5 ms jitter the mean holds within the mean tolerance above, turned into time by the
// acceleration.
TEST(PenSpeed, TheLagIsOneReport) {
  const double a = 1.0;
  for (const double jitter : {0.0, 0.5e-3}) {
    SCOPED_TRACE(jitter);
    TabletModel tablet;
    tablet.jitter_s = jitter;
    const auto reports =
        testing::synthetic_stroke(testing::accelerating_line(0.020, a), 0.25, tablet);
    PenSpeed speed;
    const PenSpeedRun run = run_pen_speed(speed, reports);
    double lag_sum = 0.0;
    for (std::size_t i = 0; i < run.estimates.size(); ++i)
      lag_sum += (run.reports[i]->true_speed_m_s - run.estimates[i]) / a;
    const double lag = lag_sum / static_cast<double>(run.estimates.size());
    const double period = 1.0 / tablet.rate_hz;
    const double tolerance =
        jitter == 0.0 ? 0.05 * period
                      : pen_speed_mean_tolerance(0.270, tablet, run.estimates.size()) / a;
    EXPECT_NEAR(lag, PenSpeed::kLagReports * period, tolerance);
    EXPECT_NEAR(speed.lag_s(), period, jitter == 0.0 ? 1e-9 : 0.25e-3);
    std::printf(
        "pen speed lag, %.1f ms jitter: measured %.3f ms (%.3f reports at %.0f Hz), "
        "reported %.3f ms\n",
        jitter * 1e3, lag * 1e3, lag / period, tablet.rate_hz, speed.lag_s() * 1e3);
  }
}

// A pen held still sends nothing: the speed holds for up to 2.5 report intervals (a late report
// is not a stop), then falls to 0.
TEST(PenSpeed, AStillPenFallsToZeroAfterTheTimeout) {
  const TabletModel tablet;
  const auto reports = testing::synthetic_stroke(testing::straight_line(0.080), 0.5, tablet);
  PenSpeed speed;
  run_pen_speed(speed, reports);
  const double last = reports.back().sample.time_s;
  const double period = 1.0 / tablet.rate_hz;
  EXPECT_GE(speed.still_timeout_s(), 2.0 * period);
  EXPECT_LE(speed.still_timeout_s(), 3.0 * period);
  EXPECT_GT(speed.speed_at(last + 0.9 * speed.still_timeout_s()), 0.070);
  EXPECT_EQ(speed.speed_at(last + 1.1 * speed.still_timeout_s()), 0.0);
  EXPECT_EQ(speed.speed_at(last + 10.0), 0.0);
}

// Reports lost on the way (three, a 30 ms gap, longer than the still timeout) give the mean speed
// over the gap; without jitter it is off by the rounding alone (0.014 mm over the gap).
TEST(PenSpeed, LostReportsGiveTheMeanSpeedOverTheGap) {
  TabletModel tablet;
  tablet.jitter_s = 0.0;
  const double v = 0.080;
  auto reports = testing::synthetic_stroke(testing::straight_line(v), 0.3, tablet);
  const double gap = reports[24].sample.time_s - reports[20].sample.time_s;
  reports.erase(reports.begin() + 21, reports.begin() + 24);
  PenSpeed speed;
  const PenSpeedRun run = run_pen_speed(speed, reports);
  ASSERT_GT(gap, speed.still_timeout_s());
  const double rounding = std::sqrt(2.0) * tablet.resolution_m;
  EXPECT_NEAR(run.estimates[21 - 2], v, rounding / gap);
  EXPECT_NEAR(run.estimates[22 - 2], v, rounding / (gap + 1.0 / tablet.rate_hz));
}

// A pen that pauses (100 ms, no reports) and sets off again: across the pause only its mean speed
// is known, so the speed rises from low and never overshoots the path's; two reports on the window
// holds no pause and gives the speed within the rounding's bound.
TEST(PenSpeed, AfterAPauseTheSpeedRisesWithoutOvershoot) {
  TabletModel tablet;
  tablet.jitter_s = 0.0;
  const double v = 0.080, pause = 0.1, period = 1.0 / tablet.rate_hz;
  const auto before = testing::synthetic_stroke(testing::straight_line(v), 0.2, tablet);
  PenSpeed speed;
  run_pen_speed(speed, before);
  const double rest_t = before.back().true_time_s - 100.0;
  std::vector<double> after;
  for (int k = 1; k <= 3; ++k) {
    const testing::PathPoint p = testing::straight_line(v)(rest_t + k * period);
    after.push_back(speed.add(before.back().sample.time_s + pause + k * period,
                              testing::quantise_to(p.x_m, tablet.resolution_m),
                              testing::quantise_to(p.y_m, tablet.resolution_m)));
  }
  const double rounding = std::sqrt(2.0) * tablet.resolution_m;
  EXPECT_LT(after[0], v * period / (pause + period) + rounding / (pause + period));
  EXPECT_LT(after[1], v);
  EXPECT_NEAR(after[2], v, rounding / (2.0 * period));
}

// Stamps that stand still or go back, and positions that are not numbers, are skipped: the speed
// stays finite and as it was.
TEST(PenSpeed, StampsThatDoNotMoveForwardAreSkipped) {
  PenSpeed speed;
  EXPECT_EQ(speed.add(1.000, 0.0100, 0.0), 0.0);
  const double v = speed.add(1.010, 0.0110, 0.0);
  EXPECT_NEAR(v, 0.1, 1e-9);
  EXPECT_EQ(speed.add(1.010, 0.0120, 0.0), v);
  EXPECT_EQ(speed.add(1.005, 0.0120, 0.0), v);
  EXPECT_EQ(speed.add(1.020, std::numeric_limits<double>::quiet_NaN(), 0.0), v);
  EXPECT_EQ(speed.skipped(), 3u);
  EXPECT_TRUE(std::isfinite(speed.speed_at(1.011)));
}

// A new stroke starts from speed 0 and keeps the tablet's measured interval.
TEST(PenSpeed, AResetStartsAStrokeAndKeepsTheMeasuredInterval) {
  TabletModel tablet;
  tablet.rate_hz = 200.0;
  const auto reports = testing::synthetic_stroke(testing::straight_line(0.080), 0.5, tablet);
  PenSpeed speed;
  run_pen_speed(speed, reports);
  const double interval = speed.report_interval_s();
  speed.reset();
  EXPECT_EQ(speed.speed(), 0.0);
  EXPECT_EQ(speed.speed_at(reports.back().sample.time_s), 0.0);
  EXPECT_EQ(speed.report_interval_s(), interval);
  EXPECT_EQ(speed.add(reports.back().sample.time_s + 1.0, 0.0, 0.0), 0.0);
}

}  // namespace
}  // namespace nibrig::rig::pen
