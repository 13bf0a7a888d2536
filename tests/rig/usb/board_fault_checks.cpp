#include "tests/rig/usb/board_fault_checks.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace nibrig::rig::usb::testing {

std::optional<double> first_flagged(const BoardHost& host, std::uint16_t flag, double after_us) {
  for (const ReceivedFrame& f : host.frames()) {
    const double t = host.sim_us_at_device_us(f.frame.device_time_us);
    if (t >= after_us && (f.frame.flags & flag)) return t;
  }
  return std::nullopt;
}

std::optional<double> disc_at_rest_since(const BoardHost& host, double after_us) {
  std::optional<double> since;
  for (const TrueSpeed& s : host.true_speeds()) {
    if (s.sim_us < after_us) continue;
    if (std::abs(s.surface_mm_s) >= 0.1) {
      since.reset();
    } else if (!since) {
      since = s.sim_us;
    }
  }
  return since;
}

void expect_stopped_since(const BoardHost& host, std::uint16_t flag, double from_us) {
  int frames = 0;
  for (const ReceivedFrame& f : host.frames()) {
    if (host.sim_us_at_device_us(f.frame.device_time_us) < from_us + 2000.0) continue;  // the loop's next tick
    ++frames;
    EXPECT_TRUE(f.frame.flags & flag) << "frame " << f.frame.sequence;
    EXPECT_FALSE(f.frame.flags & kProfileRunning) << "frame " << f.frame.sequence;
  }
  EXPECT_GT(frames, 0);
  for (const TrueSpeed& s : host.true_speeds()) {
    if (s.sim_us >= from_us + 2000.0) {
      EXPECT_EQ(s.duty, 0.0) << "at " << s.sim_us << " us";
    }
  }
}

}  // namespace nibrig::rig::usb::testing
