// The firmware's speed estimate (rig/firmware/speed_loop.c, compiled for the host) fed an encoder's
// edges at a steady rate that changes at once: the time it takes to read the new rate is its window,
// which rig/HARDWARE.md gives at the sweep's ends and at most.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "tests/rig/usb/hardware_guide.hpp"

extern "C" {
#include "rig/firmware/speed_loop.h"
}

namespace nibrig::rig::usb::testing {
namespace {

constexpr double kEstimateMmPerCount = 2.0 * M_PI * 60.0 / 4480.0;  // the reference disc's track

// Edges at `from_mm_s` for 300 ms, then at `to_mm_s`: the milliseconds until every estimate is within
// 1 % of the new speed (the window's length, to the millisecond the firmware looks at it).
double estimate_window_ms(double from_mm_s, double to_mm_s) {
  speed_estimator e{};
  const double switch_s = 0.3;
  const double from_rate = from_mm_s / kEstimateMmPerCount, to_rate = to_mm_s / kEstimateMmPerCount;
  auto edges_by = [&](double t) {  // edges passed by time t, and the last one's time
    const double n = t <= switch_s ? t * from_rate : switch_s * from_rate + (t - switch_s) * to_rate;
    const double k = std::floor(n);
    const double at = k <= switch_s * from_rate ? k / from_rate : switch_s + (k - switch_s * from_rate) / to_rate;
    return std::pair{static_cast<std::int32_t>(k), at};
  };
  double settled_ms = NAN;
  for (int ms = 1; ms <= 600; ++ms) {
    const double t = ms * 1e-3;
    const auto [count, last_edge_s] = edges_by(t);
    const float rate = speed_estimate(&e, count, static_cast<std::uint32_t>(last_edge_s * 1e6), static_cast<std::uint32_t>(t * 1e6));
    const double mm_s = rate * kEstimateMmPerCount;
    if (t <= switch_s) continue;
    if (std::abs(mm_s - to_mm_s) > 0.01 * to_mm_s) {
      settled_ms = NAN;
    } else if (std::isnan(settled_ms)) {
      settled_ms = (t - switch_s) * 1e3;
    }
  }
  return settled_ms;
}

// The guide's windows to 2 ms: the estimate reads the clock a millisecond at a time, and an edge
// can fall either side of a tick.
TEST(FirmwareSpeedEstimate, ItsWindowIsTheGuidesAtTheSweepsEndsAndAtMost) {  // (50 ms: a rule of its code)
  struct Case {
    const char* figure;
    double from, to;
  };
  for (const Case& c : {Case{"speed estimate's window at 250 mm/s", 200.0, 250.0},
                        Case{"speed estimate's window at 17 mm/s", 20.0, 17.0}}) {
    const double window = estimate_window_ms(c.from, c.to);
    std::printf("%s: %.0f ms\n", c.figure, window);
    RecordProperty(std::string(c.figure), std::to_string(window));
    EXPECT_NEAR(window, hardware_guide_figure(c.figure), 2.0) << c.figure;
  }
}

}  // namespace
}  // namespace nibrig::rig::usb::testing
