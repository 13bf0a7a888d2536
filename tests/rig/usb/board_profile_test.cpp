// A speed profile run by the firmware itself on the simulated turntable, in simulated time: uploaded
// with PROFILE_BEGIN/WRITE/END, started, and followed (ramps and a step) as the frames report it;
// then held at its last speed in mode 3.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "rig/speed_profile.hpp"
#include "tests/rig/usb/board_host.hpp"

namespace nibrig::rig::usb::testing {
namespace {

// Ramps up, holds, steps, holds, ramps down, holds: what a sweep's profile is made of.
const std::vector<ProfilePoint> kBoardProfile = {{0.0, 0.020}, {0.3, 0.100}, {0.6, 0.100}, {0.6, 0.200},
                                                 {0.9, 0.200}, {1.2, 0.050}, {1.4, 0.050}};

// The profile's speed at `t_s` (mm/s): straight lines between points, the later of two at one time.
double board_profile_mm_s(double t_s) {
  const auto& p = kBoardProfile;
  if (t_s >= p.back().time_s) return p.back().speed_m_s * 1e3;
  std::size_t i = 0;
  while (i + 1 < p.size() && p[i + 1].time_s <= t_s) ++i;
  const double f = (t_s - p[i].time_s) / (p[i + 1].time_s - p[i].time_s);
  return (p[i].speed_m_s + (p[i + 1].speed_m_s - p[i].speed_m_s) * f) * 1e3;
}

TEST(BoardProfile, TheFramesFollowAnUploadedProfileThenHoldItsEnd) {
  BoardHost host;
  host.require_out(Request::kProfileBegin, static_cast<std::uint16_t>(kBoardProfile.size()));
  host.require_out(Request::kProfileWrite, 0, 0, encode_points(kBoardProfile));
  host.require_out(Request::kProfileEnd);
  host.require_out(Request::kSetStreaming, 1);
  host.run_us(10'000.0);
  host.clear_records();
  host.require_out(Request::kStartProfile);
  // The firmware's profile clock starts as it handles the request, during the transfer that just
  // ended: within the transfer's few tens of microseconds of this.
  const std::uint64_t started_us = host.board().device_us();
  host.run_us(1'000'000.0);
  EXPECT_EQ(host.status().mode, Mode::kProfile);
  host.run_us(600'000.0);
  const DeviceStatus done = host.status();
  EXPECT_EQ(done.mode, Mode::kProfileDone);
  EXPECT_EQ(done.fault, Fault::kNone);

  // Away from the start and the step (each given 150 ms to settle, the speed loop's settling with
  // margin), the reported speed follows the profile within 2 % of the speed plus 0.5 mm/s: the
  // loop's steady error is under 1 %, and on a ramp its feed-forward carries both the speed and the
  // torque that accelerates the disc. On a ramp the reported speed also lags: the firmware estimates
  // it over at least 10 ms of edges, half of that behind the ramp. For 50 ms after a ramp's end
  // that torque's feed-forward stops at once while the disc lags by a few mm/s: 10 % there (the
  // overshoot a sweep tolerates).
  double worst_ramp = 0.0, worst_hold = 0.0, worst_corner = 0.0;
  int checked = 0;
  for (const ReceivedFrame& f : host.frames()) {
    if (f.frame.device_time_us < started_us) continue;
    const double t_s = static_cast<double>(f.frame.device_time_us - started_us) * 1e-6;
    // After the last point: mode 3, no longer running, its speed held.
    if (t_s > 1.41) {
      EXPECT_FALSE(f.frame.flags & kProfileRunning) << "at " << t_s << " s";
    } else if (t_s > 0.01 && t_s < 1.39) {
      EXPECT_TRUE(f.frame.flags & kProfileRunning) << "at " << t_s << " s";
    }
    if (t_s < 0.15 || (t_s >= 0.6 && t_s < 0.75)) continue;
    const double target = board_profile_mm_s(t_s), reported = f.frame.speed_m_s * 1e3;
    const double error = std::abs(reported - target);
    const bool corner = (t_s >= 0.3 && t_s < 0.35) || (t_s >= 0.9 && t_s < 0.95) || (t_s >= 1.2 && t_s < 1.25);
    const bool ramp = t_s < 0.3 || (t_s >= 0.9 && t_s < 1.2);
    double& worst = corner ? worst_corner : ramp ? worst_ramp : worst_hold;
    worst = std::max(worst, error / target);
    const double slope = std::abs(board_profile_mm_s(t_s + 0.001) - board_profile_mm_s(t_s)) / 0.001;
    const double tolerance = corner ? 0.10 * target + 0.5 : 0.02 * target + 0.5 + (ramp ? slope * 0.005 : 0.0);
    EXPECT_LT(error, tolerance) << "at " << t_s << " s: " << reported << " mm/s for " << target;
    ++checked;
  }
  EXPECT_GT(checked, 1200);
  std::printf("profile: worst error on ramps %.2f %%, on holds %.2f %%, 50 ms after a ramp's end %.2f %%\n",
              100 * worst_ramp, 100 * worst_hold, 100 * worst_corner);
  RecordProperty("worst_corner_error_pct", std::to_string(100 * worst_corner));
  RecordProperty("worst_ramp_error_pct", std::to_string(100 * worst_ramp));
  RecordProperty("worst_hold_error_pct", std::to_string(100 * worst_hold));
}

}  // namespace
}  // namespace nibrig::rig::usb::testing
