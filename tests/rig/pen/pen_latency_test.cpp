// Stroke to sound through the pen path, beside the mouse path, on the tests' JACK server: strokes
// drawn on the emulated tablet (libinput, the reader's thread, PenContact, play_pen's loop, the
// engine, the JACK graph) and strokes posted as the pad posts a mouse's (LiveAudition::set_contact
// on the control thread), each timed from its start to the cycle in which an independent libjack
// client first hears it. Both on CLOCK_MONOTONIC: the kernel's stamp of the tablet's first tip-down
// report, and the listener's callback read at its wake-up. JACK's own cycle stamps are not used:
// its clock filter may put a cycle's start before the late wake-up that rendered it, so a stroke
// would seem heard before it began.
#include <gtest/gtest.h>
#include <jack/jack.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>
#include <vector>

#include "playback/live_audition.hpp"
#include "rig/pen/pen_clock.hpp"
#include "rig/pen/pen_play.hpp"
#include "tests/playback/jack_recorder.hpp"
#include "tests/playback/jack_stream_settings.hpp"
#include "tests/rig/pen/emulated_tablet.hpp"
#include "tests/rt/test_voices.hpp"
#include "tests/support/jack_server.hpp"

namespace nibrig::rig::pen {
namespace {

using namespace std::chrono_literals;

constexpr int kStrokesPerPath = 4;
constexpr double kStrokeSeconds = 0.2, kRestSeconds = 0.35;

void sleep_until_s(double t) {
  std::this_thread::sleep_for(std::chrono::duration<double>(std::max(0.0, t - pen_clock_now_s())));
}

// When each recorded sample was heard: its cycle's wake-up in the listener, on CLOCK_MONOTONIC.
std::vector<double> heard_times(const playback::testing::JackRecorder& ear) {
  std::vector<double> t(ear.samples(0).size(), -1.0);
  for (const auto& cycle : ear.cycles()) {
    for (std::size_t i = 0; i < cycle.frames && cycle.start + i < t.size(); ++i)
      t[cycle.start + i] = cycle.heard_monotonic_s;
  }
  return t;
}

// From `start_s` to the cycle of the first sample clearly above what sounded just before it (the
// last stroke's ring-down, 350 ms old): four times the largest of the 30 ms before, and at least a
// thousandth of the stroke's loudest, so that the numbers' own noise is never taken for a start.
double onset_after(const std::vector<float>& x, const std::vector<double>& t, double start_s) {
  const auto quiet = std::lower_bound(t.begin(), t.end(), start_s - 0.03) - t.begin();
  // Cycles heard after the start: the only ones the stroke can be in.
  const auto first = std::upper_bound(t.begin(), t.end(), start_s) - t.begin();
  const auto end =
      std::lower_bound(t.begin(), t.end(), start_s + kStrokeSeconds + 0.05) - t.begin();
  float floor = 0.0f, peak = 0.0f;
  for (auto i = quiet; i < first; ++i)
    floor = std::max(floor, std::abs(x[static_cast<std::size_t>(i)]));
  for (auto i = first; i < end; ++i)
    peak = std::max(peak, std::abs(x[static_cast<std::size_t>(i)]));
  const float threshold = std::max(4.0f * floor, 1e-3f * peak);
  for (auto i = first; i < end; ++i) {
    if (std::abs(x[static_cast<std::size_t>(i)]) > threshold)
      return t[static_cast<std::size_t>(i)] - start_s;
  }
  return NAN;
}

struct PathLatency {
  double mean_s = 0.0, median_s = 0.0, worst_s = 0.0;
  int heard = 0;
};

PathLatency summarise(const std::vector<double>& onsets) {
  PathLatency l;
  std::vector<double> heard;
  for (double o : onsets)
    if (std::isfinite(o)) heard.push_back(o);
  l.heard = static_cast<int>(heard.size());
  if (heard.empty()) return l;
  std::sort(heard.begin(), heard.end());
  for (double o : heard) l.mean_s += o;
  l.mean_s /= l.heard;
  const std::size_t mid = heard.size() / 2;
  l.median_s = heard.size() % 2 ? heard[mid] : 0.5 * (heard[mid - 1] + heard[mid]);
  l.worst_s = heard.back();
  return l;
}

TEST(PenStrokeToSound, ThePenPathIsTimedBesideTheMousePathOnJack) {
  nibrig::testing::JackServer server;
  UMockdevTestbed* testbed = umockdev_testbed_new();
  {
    testing::EmulatedTablet tablet(testbed, testing::wacom_intuos_s());
    playback::LiveAudition audition(rt::EngineSettings{});
    audition.load(0,
                  {"cryon", "small stylus", rt::testing::small_stylus(),
                   rt::testing::catalog_spectrum("cryon", "note")},
                  7);
    audition.open(playback::testing::jack_settings("audition"));
    const double seconds = 2 * kStrokesPerPath * (kStrokeSeconds + kRestSeconds) + 1.5;
    playback::testing::JackRecorder ear("ear", 1, static_cast<std::size_t>(seconds * 48000));
    ASSERT_TRUE(ear.connect("audition:outport 0", 0));
    ear.start();
    std::this_thread::sleep_for(300ms);

    // The mouse path: the pad posts a mouse's contact on its control thread.
    std::vector<double> mouse_starts;
    for (int k = 0; k < kStrokesPerPath; ++k) {
      const double t = pen_clock_now_s();
      mouse_starts.push_back(t);
      audition.set_contact(0.1, 2.0);
      sleep_until_s(t + kStrokeSeconds);
      audition.set_contact(0.0, 0.0);
      sleep_until_s(t + kStrokeSeconds + kRestSeconds);
    }

    // The pen path: the same strokes drawn on the tablet, 100 mm/s under half its pressure, the
    // engine now the pen loop's.
    std::vector<double> pen_starts;
    PenStylus stylus("intuos");
    std::stop_source stop;
    std::thread loop([&] { play_pen(audition, stylus, 0.0, stop.get_token()); });
    const double period = 1.0 / tablet.model().report_hz;
    for (int k = 0; k < kStrokesPerPath; ++k) {
      // Each report stamped when it is written, as the kernel stamps an event when it arrives.
      const double t0 = pen_clock_now_s();
      tablet.proximity_in(t0, 20.0, 40.0);
      const double down = t0 + period;
      sleep_until_s(down);
      pen_starts.push_back(pen_clock_now_s());
      for (double t = down; t < down + kStrokeSeconds; t += period) {
        sleep_until_s(t);
        const double now = pen_clock_now_s();
        tablet.report(now, 20.0 + 100.0 * (now - down), 40.0, 0.5);
      }
      const double up = down + kStrokeSeconds;
      sleep_until_s(up);
      tablet.report(pen_clock_now_s(), 20.0 + 100.0 * kStrokeSeconds, 40.0, 0.0);
      sleep_until_s(up + period);
      tablet.proximity_out(pen_clock_now_s());
      sleep_until_s(up + kRestSeconds);
    }
    stop.request_stop();
    loop.join();
    ASSERT_TRUE(ear.wait_full(30s)) << "recorded " << ear.recorded() << " frames";

    const auto times = heard_times(ear);
    std::vector<double> mouse, pen;
    for (double s : mouse_starts) mouse.push_back(onset_after(ear.samples(0), times, s));
    for (double s : pen_starts) pen.push_back(onset_after(ear.samples(0), times, s));
    const PathLatency m = summarise(mouse), p = summarise(pen);
    for (std::size_t k = 0; k < pen.size(); ++k)
      std::printf("stroke %zu: mouse %.2f ms, pen %.2f ms\n", k + 1, 1e3 * mouse[k], 1e3 * pen[k]);
    // The device plays a cycle's output after its playback latency, the same for both paths.
    jack_latency_range_t playback{0, 0};
    if (jack_port_t* out = jack_port_by_name(ear.client(), "system:playback_1")) {
      jack_port_get_latency_range(out, JackPlaybackLatency, &playback);
    }
    const double device_s = playback.max / 48000.0;
    RecordProperty("device_playback_ms", std::to_string(1e3 * device_s));
    RecordProperty("mouse_mean_ms", std::to_string(1e3 * m.mean_s));
    RecordProperty("mouse_median_ms", std::to_string(1e3 * m.median_s));
    RecordProperty("mouse_worst_ms", std::to_string(1e3 * m.worst_s));
    RecordProperty("pen_mean_ms", std::to_string(1e3 * p.mean_s));
    RecordProperty("pen_median_ms", std::to_string(1e3 * p.median_s));
    RecordProperty("pen_worst_ms", std::to_string(1e3 * p.worst_s));
    std::printf(
        "stroke to the cycle a listener hears it in, on JACK (48 kHz, 64-frame periods): mouse "
        "path %.2f ms median, "
        "%.2f worst; pen path %.2f ms median, %.2f worst (%d and %d strokes heard); the device "
        "then plays "
        "it %.2f ms later (its playback latency)\n",
        1e3 * m.median_s, 1e3 * m.worst_s, 1e3 * p.median_s, 1e3 * p.worst_s, m.heard, p.heard,
        1e3 * device_s);
    EXPECT_EQ(m.heard, kStrokesPerPath);
    EXPECT_EQ(p.heard, kStrokesPerPath);
    // The pen's first report has no speed yet (PenSpeed needs a second), so its sound starts one
    // report later than its tip; beyond that it shares the mouse path's engine and graph. Bound on
    // the typical stroke (the median): the mouse path's, one report, and 5 ms for libinput, the
    // reader, the loop's 1 ms turn and a scheduler on two busy cores. A stroke whose reader was
    // scheduled late (19 ms, once in 25 runs under ASan) may take one report more, no further.
    EXPECT_LT(p.median_s, m.median_s + period + 5e-3);
    EXPECT_LT(p.worst_s, m.worst_s + 2 * period + 5e-3);
    // And the mouse path itself within a few periods of the graph (64 frames = 1.33 ms each).
    EXPECT_LT(m.worst_s, 10e-3);
    EXPECT_EQ(audition.engine_stats().refused_commands, 0u);
  }
  g_object_unref(testbed);
}

}  // namespace
}  // namespace nibrig::rig::pen
