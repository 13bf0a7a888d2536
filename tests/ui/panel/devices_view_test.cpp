// The devices view says what runs: the form shows the stream's own period and device (JACK imposes
// its server's period whatever was asked), and the running block gives the period and latency in
// ms, the callback's load over the last seconds and the xruns of the last minute, from a history
// the UI thread keeps of the audio thread's cumulative counts (StreamMonitor, checked here on made-up
// counts first, then on a real JACK server).
#include "ui/panel/devices_view.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "tests/support/jack_server.hpp"
#include "tests/ui/panel/headless_imgui.hpp"

namespace nibrig::ui::panel {
namespace {

// Made-up counts, sampled every 0.1 s as frames would: `blocks` callbacks of `block_s` each per
// sample, the device's and the engine's xrun counts as given.
struct MonitorFeed {
  StreamMonitor monitor;
  rt::EngineStats engine;
  std::uint64_t device = 0;
  int step = 0;
  double now() const { return 0.1 * step; }
  void run_until(double t, std::uint64_t blocks, double block_s) {
    while (now() < t - 1e-9) {
      ++step;
      engine.callbacks += blocks;
      engine.callback_time_histogram[rt::callback_time_bin(block_s)] += blocks;
      engine.max_callback_s = std::max(engine.max_callback_s, block_s);
      monitor.sample(now(), engine, device);
    }
  }
};

TEST(StreamMonitor, CountsTheXrunsOfTheLastMinuteAndTheLoadOfTheLastSeconds) {
  MonitorFeed f;
  const double period_s = 1e-3;
  f.monitor.sample(0.0, f.engine, 0);
  f.run_until(5.0, 100, 0.5e-3);
  f.device += 1;  // one at 5 s
  f.run_until(20.0, 100, 0.5e-3);
  auto x = f.monitor.xruns();
  EXPECT_EQ(x.device, 1u);
  EXPECT_NEAR(x.window_s, 20.0, 1e-9);  // since sampling began: shorter than the minute
  f.run_until(40.0, 100, 0.5e-3);
  f.device += 1;  // one at 40 s
  f.run_until(50.0, 100, 0.5e-3);
  f.engine.overruns += 1;  // one of our own at 50 s
  f.run_until(75.0, 100, 0.5e-3);
  f.device += 2;  // two at 75 s
  f.run_until(90.0, 100, 0.5e-3);
  x = f.monitor.xruns();
  // The window reaches back to the newest sample at or before 30 s: the one at 5 s is out.
  EXPECT_EQ(x.device, 3u);
  EXPECT_EQ(x.own, 1u);
  // A minute, to the 0.1 s the history keeps its samples at.
  EXPECT_NEAR(x.window_s, 60.0, StreamMonitor::kSampleEveryS + 1e-9);

  // Every block took 0.5 ms of a 1 ms period: the mean is read from the histogram's bin, whose
  // geometric middle is within a factor 10^0.05 (12.2 %) of any time in it; the worst is capped by
  // the longest block, 0.5 ms exactly.
  auto load = f.monitor.load(period_s);
  ASSERT_TRUE(load.has_value());
  EXPECT_NEAR(load->mean, 0.5, 0.5 * 0.123);
  EXPECT_DOUBLE_EQ(load->worst, 0.5);
  EXPECT_NEAR(load->window_s, StreamMonitor::kLoadWindowS, StreamMonitor::kSampleEveryS + 1e-9);
  EXPECT_EQ(load->blocks, static_cast<std::uint64_t>(std::lround(load->window_s / 0.1)) * 100u);
  // A second of late blocks (2 ms each): the worst is their time, the mean rises.
  f.run_until(91.0, 100, 2e-3);
  load = f.monitor.load(period_s);
  ASSERT_TRUE(load.has_value());
  EXPECT_DOUBLE_EQ(load->worst, 2.0);  // the bin's upper edge is above 2 ms; the longest block is 2 ms
  EXPECT_GT(load->mean, 0.5 * 1.123);
  // Once they are older than the load's window, the worst is the bin of 0.5 ms again (its upper
  // edge: the longest block, 2 ms, no longer caps it tighter).
  f.run_until(91.0 + StreamMonitor::kLoadWindowS + 0.5, 100, 0.5e-3);
  load = f.monitor.load(period_s);
  ASSERT_TRUE(load.has_value());
  EXPECT_GE(load->worst, 0.5);
  EXPECT_LE(load->worst, 0.5 * 1.259);  // ten bins a decade: an edge at most 10^0.1 above

  // A stream opened afresh: its counts start at 0 and the history starts again.
  f.device = 0;
  f.engine = {};
  f.run_until(f.now() + 1.0, 100, 0.5e-3);
  x = f.monitor.xruns();
  EXPECT_EQ(x.device, 0u);
  EXPECT_NEAR(x.window_s, 0.9, 1e-9);  // from the first sample of the new stream
}

TEST(DevicesView, ShowsThePeriodTheLatencyTheLoadAndTheXrunsOfTheStreamThatRunsOnJack) {
  nibrig::testing::JackServer server;  // 48 kHz, period 64 (tests/support/jack_server.hpp)
  testing::HeadlessImGui imgui;
  PanelAudio audio(model::design::ToolSoundOptions{});
  DevicesView view(audio);
  // The request's defaults: period 256 and no device named. JACK runs its server's 64 frames.
  view.set_request(DeviceRequest{"jack", "", 1, 256});
  imgui.frame([&] { view.draw(); });
  view.open();
  ASSERT_EQ(view.error(), "");
  // Frames for a second and a half: hundreds of callbacks (one each 1.3 ms) and 15 samples.
  const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(1500);
  while (std::chrono::steady_clock::now() < until) {
    imgui.frame([&] { view.draw(); });
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  const auto info = audio.audition().stream_info();
  ASSERT_TRUE(info.has_value());

  // The form shows what runs, not what was asked.
  EXPECT_EQ(view.shown_request().period_frames, 64u);
  EXPECT_FALSE(view.shown_request().device.empty());
  EXPECT_EQ(view.shown_request().device, info->device);
  EXPECT_EQ(view.shown_request().api, "jack");

  const auto& r = view.running();
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(r->period_frames, 64u);
  EXPECT_EQ(r->sample_rate, 48000u);
  // Computed from two integers: only the division's rounding, far below 1e-9 ms.
  EXPECT_NEAR(r->period_ms, 1e3 * 64.0 / 48000.0, 1e-9);
  // The JACK back end reports the playback port's latency (128 frames on the dummy driver's two
  // periods); a back end that reports none is shown as one period, the least a block waits.
  if (r->latency_reported) {
    EXPECT_EQ(r->latency_frames, info->latency_frames);
  } else {
    EXPECT_EQ(r->latency_frames, 64);
  }
  EXPECT_NEAR(r->latency_ms, 1e3 * static_cast<double>(r->latency_frames) / 48000.0, 1e-9);

  // The engine renders silence in each callback: some microseconds of a 1.33 ms period, so more
  // than nothing and (on average) well within the period even on a loaded machine.
  ASSERT_TRUE(r->load.has_value()) << "no callback ran within the load's window";
  EXPECT_GT(r->load->mean, 0.0);
  EXPECT_LE(r->load->mean, 1.0);
  EXPECT_GE(r->load->worst, r->load->mean);
  EXPECT_GT(r->load->blocks, 100u);  // 1.5 s at 750 callbacks a second, at least a fraction of it
  // Xruns: the view's count is of the time since it was shown (1.5 s), so no more than the stream
  // counted in all; the window is that time, to the 0.1 s the history keeps.
  const auto stats = audio.audition().output_stats();
  ASSERT_TRUE(stats.has_value());
  EXPECT_LE(r->xruns.device, stats->output_underflows);
  EXPECT_GT(r->xruns.window_s, 1.0);
  EXPECT_LT(r->xruns.window_s, StreamMonitor::kXrunWindowS);
  audio.close();
}

}  // namespace
}  // namespace nibrig::ui::panel
