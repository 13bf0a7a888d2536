// A stroke drawn on the emulated XP-Pen Deco 01 V2, at its 266 reports a second, recorded through
// the real reader (PenStylus, StrokeRecorder) and played back as `render --trajectory` plays a file:
// the trajectory reader accepts its rate, and the stroke the engine is given has its speed and force.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>
#include <vector>

#include "model/io/paper_drawing.hpp"
#include "rig/pen/pen_stylus.hpp"
#include "rig/pen/stroke_recorder.hpp"
#include "rt/stroke_request.hpp"
#include "tests/rig/pen/emulated_tablet.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::rig::pen {
namespace {

using testing::EmulatedTablet;

TEST(PenRecordedStroke, AStrokeFromTheXpPenAt266HzIsReadBackAndRendered) {
  const auto dir = nibrig::test::scratch_dir("pen_recorded_xp_pen");
  UMockdevTestbed* testbed = umockdev_testbed_new();
  std::filesystem::path file;
  const testing::EvdevTabletModel m = testing::xp_pen_deco_01_v2();
  constexpr double kSpeed = 0.080, kPressure = 0.5, kSeconds = 1.0;
  const double period = 1.0 / m.report_hz;
  const int reports = static_cast<int>(kSeconds * m.report_hz);
  double span_s = 0.0;
  {
    EmulatedTablet tablet(testbed, m);
    PenStylus stylus(tablet.devnode());
    StrokeRecorder recorder({dir, "pen", "tablet", stylus.tablet().name});
    stylus.on_sample([&recorder](const PenSample& s, double force_n) { recorder.add(s, force_n); });
    file = recorder.start();
    // Along x, every report one period after the last, from the pen coming near to it leaving.
    const double t0 = EmulatedTablet::now_s() + 0.01;
    std::this_thread::sleep_for(std::chrono::duration<double>(t0 - EmulatedTablet::now_s()));
    tablet.proximity_in(t0, 20.0, 50.0);
    for (int k = 1; k <= reports + 1; ++k) {
      const double t = t0 + k * period;
      std::this_thread::sleep_for(std::chrono::duration<double>(std::max(0.0, t - EmulatedTablet::now_s())));
      tablet.report(t, 20.0 + 1e3 * kSpeed * (t - t0), 50.0, k <= reports ? kPressure : 0.0);
    }
    tablet.proximity_out(t0 + (reports + 2) * period);
    span_s = (reports + 2) * period;
    // The reader's thread delivers within milliseconds; the recorder writes what it was given.
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    const auto summary = recorder.stop();
    ASSERT_TRUE(summary);
    ASSERT_TRUE(summary->kept);
    EXPECT_GE(summary->rows, static_cast<std::uint64_t>(reports));
  }
  g_object_unref(testbed);

  // Accepted, at the tablet's rate: the rows' stamps are whole milliseconds, so the rate over the
  // recording's span is off by at most 1 ms of rounding at either end.
  const model::io::DrawingTrajectory d = model::io::read_paper_drawing(file);
  const double rate_tolerance = m.report_hz * 1e-3 / span_s;
  EXPECT_NEAR(d.frame_rate_hz, m.report_hz, rate_tolerance);
  // Each row's speed is its step's length over a frame: the positions lie on the tablet's 0.01 mm
  // grid (and are written to 1e-4 mm), so a step is off by up to √2 × 0.01 mm of its 0.3 mm; the
  // rate adds its own share.
  const double step_m = kSpeed * period;
  const double speed_tolerance = kSpeed * (std::sqrt(2.0) * (1e-3 / m.resolution + 1e-7) / step_m + rate_tolerance / m.report_hz);
  std::size_t touching = 0;
  for (std::size_t i = 1; i < d.time_s.size(); ++i) {
    if (!d.touching[i] || !d.touching[i - 1]) continue;
    EXPECT_NEAR(d.speed_m_s[i], kSpeed, speed_tolerance) << "row " << i;
    ++touching;
  }
  EXPECT_GE(touching, static_cast<std::size_t>(reports - 3));

  // `render --trajectory` takes it: the stroke it makes gives the engine 80 mm/s and the recorded
  // force through the middle of the stroke, at the engine's 48 kHz.
  rt::StrokeRequest request;
  request.trajectory = file;
  const rt::Stroke stroke = rt::make_stroke(request);
  EXPECT_NEAR(stroke.natural_seconds, d.time_s.back(), 1e-9);
  constexpr double kRate = 48000.0;
  const auto first = static_cast<std::uint64_t>(0.3 * kRate);
  std::vector<double> speed(static_cast<std::size_t>(0.4 * kRate)), force(speed.size());
  stroke.source->fill(first, kRate, speed.data(), force.data(), speed.size());
  const double force_recorded = d.normal_force_N[d.normal_force_N.size() / 2];
  for (std::size_t n = 0; n < speed.size(); n += 480) {
    // Between two rows the speed is interpolated from theirs: within the rows' tolerance.
    EXPECT_NEAR(speed[n], kSpeed, speed_tolerance) << n;
    EXPECT_NEAR(force[n], force_recorded, 1e-3) << n;  // the writer's 1e-4 N, and one pressure
  }
  EXPECT_GT(force_recorded, 0.4 * kDefaultFullScaleN);
}

}  // namespace
}  // namespace nibrig::rig::pen
