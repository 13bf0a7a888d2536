// The firmware's speed loop on the simulated turntable, in simulated time: SET_SPEED steps from rest
// and between the paper's slowest and fastest speeds, measured both as the disc truly turns (the
// harness's physics) and as the frames report it (the firmware's encoder estimate).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "tests/rig/usb/board_host.hpp"

namespace nibrig::rig::usb::testing {
namespace {

constexpr double kStepHoldUs = 800'000.0;
constexpr double kSteadyFromUs = 400'000.0;  // the steady window: 0.4 s to 0.8 s after the step

struct StepResponse {
  double rise_ms = NAN;       // 10 % to 90 % of the step
  double overshoot = NAN;     // beyond the target, a fraction of the step
  double settling_ms = NAN;   // last time outside 2 % of the step
  double steady_error = NAN;  // mean over the steady window, a fraction of the target
  double ripple = NAN;        // standard deviation over the steady window, a fraction of the target
};

// `trace` is (simulated us, mm/s), in time order; the step from `from` to `to` at `t0`.
StepResponse step_response(const std::vector<std::pair<double, double>>& trace, double t0, double from, double to) {
  StepResponse r;
  const double step = to - from;
  double t10 = NAN, t90 = NAN, peak = from, last_outside = t0, steady_sum = 0.0, steady_squares = 0.0;
  int steady_n = 0;
  for (const auto& [t, v] : trace) {
    if (t < t0 || t > t0 + kStepHoldUs) continue;
    const double progress = (v - from) / step;
    if (std::isnan(t10) && progress >= 0.1) t10 = t;
    if (std::isnan(t90) && progress >= 0.9) t90 = t;
    if (step > 0 ? v > peak : v < peak) peak = v;
    if (std::abs(v - to) > 0.02 * std::abs(step)) last_outside = t;
    if (t >= t0 + kSteadyFromUs) {
      steady_sum += v;
      steady_squares += v * v;
      ++steady_n;
    }
  }
  r.rise_ms = (t90 - t10) * 1e-3;
  r.overshoot = std::max(0.0, (peak - to) / step);
  r.settling_ms = (last_outside - t0) * 1e-3;
  if (steady_n > 0) {
    const double mean = steady_sum / steady_n;
    r.steady_error = (mean - to) / to;
    r.ripple = std::sqrt(std::max(0.0, steady_squares / steady_n - mean * mean)) / to;
  }
  return r;
}

std::vector<std::pair<double, double>> true_trace(const BoardHost& host) {
  std::vector<std::pair<double, double>> trace;
  for (const TrueSpeed& s : host.true_speeds()) trace.emplace_back(s.sim_us, s.surface_mm_s);
  return trace;
}

std::vector<std::pair<double, double>> reported_trace(const BoardHost& host) {
  std::vector<std::pair<double, double>> trace;
  for (const ReceivedFrame& f : host.frames()) {
    trace.emplace_back(host.sim_us_at_device_us(f.frame.device_time_us), f.frame.speed_m_s * 1e3);
  }
  return trace;
}

class BoardSpeedLoop : public ::testing::Test {
 protected:
  explicit BoardSpeedLoop(TurntablePhysics physics = {}) : host_({}, physics) {}

  void SetUp() override {
    host_.require_out(Request::kSetStreaming, 1);
    host_.run_us(20'000.0);
  }

  // Steps to `to` and holds it; prints and records the response, and checks it against what a sweep
  // needs: the paper's sweeps hold each speed about a second, so the speed must have settled well
  // within 0.2 s, must not overshoot by more than 10 % (a brief speed the sweep did not ask for),
  // and must hold the target within 1 % (the speed bins' resolution is coarser), its ripple under
  // 2 %.
  void step_to(double from, double to, const std::string& name, double settling_limit_ms = 200.0,
               double reported_settling_limit_ms = 0.0) {  // 0: the same as the true speed's
    host_.clear_records();
    host_.set_speed_mm_s(static_cast<float>(to));
    const double t0 = host_.sim_us();
    host_.run_us(kStepHoldUs);
    const StepResponse truth = step_response(true_trace(host_), t0, from, to);
    const StepResponse reported = step_response(reported_trace(host_), t0, from, to);
    for (const auto& [kind, r] : {std::pair{"true", truth}, std::pair{"reported", reported}}) {
      std::printf("%-16s %-9s rise %6.1f ms  overshoot %5.2f %%  settling %6.1f ms  steady error %+6.3f %%  ripple %5.2f %%\n",
                  name.c_str(), kind, r.rise_ms, 100 * r.overshoot, r.settling_ms, 100 * r.steady_error, 100 * r.ripple);
    }
    for (const auto& [kind, r] : {std::pair{"true", truth}, std::pair{"reported", reported}}) {
      const std::string key = name + "_" + kind;
      RecordProperty(key + "_rise_ms", std::to_string(r.rise_ms));
      RecordProperty(key + "_overshoot_pct", std::to_string(100 * r.overshoot));
      RecordProperty(key + "_settling_ms", std::to_string(r.settling_ms));
      RecordProperty(key + "_steady_error_pct", std::to_string(100 * r.steady_error));
      RecordProperty(key + "_ripple_pct", std::to_string(100 * r.ripple));
      const StepResponse& checked = r;
      const bool reported_own = kind != std::string("true") && reported_settling_limit_ms > 0.0;
      EXPECT_LT(checked.settling_ms, reported_own ? reported_settling_limit_ms : settling_limit_ms) << key;
      EXPECT_LT(checked.overshoot, 0.10) << key;
      EXPECT_LT(std::abs(checked.steady_error), 0.01) << key;
      EXPECT_LT(checked.ripple, 0.02) << key;
      // A rise that is measured at all: the step happened and the loop moved the disc. (The
      // reported speed may rise within one frame: the estimate waits for its first edges.)
      EXPECT_FALSE(std::isnan(checked.rise_ms)) << key;
    }
  }

  BoardHost host_;
};

// A load the feed-forward does not know: the normal force over twice the paper's 2.2 N on a
// grippier material (mu 0.6), the contact's torque four times what the loop's offset assumes. At
// 17 mm/s the feed-forward then leaves the disc barely turning and the integral must find the load,
// which it does from 50 ms after the step: settled within 0.4 s, still well inside a 1 s hold.
TEST_F(BoardSpeedLoop, StepsUnderALoadItWasNotTunedFor) {
  host_.board().set_normal_force(5.0);
  host_.board().set_friction(0.6);
  step_to(0.0, 17.0, "heavy_rest_to_17", 400.0);
  step_to(17.0, 250.0, "heavy_17_to_250");
}

// A real encoder: channel B a sixth of a count out of phase with A, A's duty cycle 10 % off.
// Counted over a whole number of quadrature cycles those errors cancel; over the few counts the
// estimate takes at 17 mm/s they do not all, and the reported speed ripples.
TurntablePhysics uneven_encoder() {
  TurntablePhysics p;
  p.encoder_phase_error = 0.17;
  p.encoder_duty_error = 0.1;
  return p;
}

class BoardSpeedLoopUnevenEncoder : public BoardSpeedLoop {
 protected:
  BoardSpeedLoopUnevenEncoder() : BoardSpeedLoop(uneven_encoder()) {}
};

// The disc itself settles as fast as with a perfect encoder. The reported speed's ripple (0.6 % at
// 250 mm/s, a standard deviation) crosses the 2 % band now and then for a while after the step,
// which the current-limited start (55 ms of rise) leaves later than it was: 300 ms for that trace.
TEST_F(BoardSpeedLoopUnevenEncoder, StepsFromRestTo17AndOnTo250) {
  step_to(0.0, 17.0, "uneven_rest_to_17");
  step_to(17.0, 250.0, "uneven_17_to_250", 200.0, 300.0);
}

TEST_F(BoardSpeedLoop, StepsFromRestTo17AndOnTo250) {
  step_to(0.0, 17.0, "rest_to_17");
  step_to(17.0, 250.0, "17_to_250");
}

TEST_F(BoardSpeedLoop, StepsFromRestTo250AndBackTo17) {
  step_to(0.0, 250.0, "rest_to_250");
  step_to(250.0, 17.0, "250_to_17");
}

}  // namespace
}  // namespace nibrig::rig::usb::testing
