// One stroke for the whole panel, checked on what a real JACK server receives: the design view's
// sound follows a stroke changed after it started (the bug: it kept the rig's sweep), the status
// line says the stroke that plays, and the stroke a person left is the one every view plays after
// a relaunch. A sweep from 17 to 250 mm/s swells and fades every 3 s; a constant speed holds its
// level, so the two are told apart by how much the level moves over 3 s of recording.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <thread>

#include "rt/stroke_request.hpp"
#include "tests/playback/jack_recorder.hpp"
#include "tests/support/jack_server.hpp"
#include "tests/ui/panel/design_cache.hpp"
#include "tests/ui/panel/panel_test_setup.hpp"
#include "ui/panel/panel.hpp"
#include "ui/panel/panel_settings.hpp"
#include "ui/panel/panel_window.hpp"

namespace nibrig::ui::panel {
namespace {

using namespace std::chrono_literals;

// How much the level moves: the standard deviation of the natural log of the RMS in 300 ms windows
// over `seconds` of what the panel sends JACK, the panel drawing at about a screen's pace meanwhile.
double level_spread(Panel& panel, const std::function<void()>& frame, double seconds) {
  const std::size_t frames = static_cast<std::size_t>(seconds * 48000.0), window = 14400;
  playback::testing::JackRecorder ear("stroke-ear", 1, frames);
  EXPECT_TRUE(ear.connect("nibrig-panel:outport 0", 0));
  ear.start();
  const auto deadline = std::chrono::steady_clock::now() + 30s;
  while (ear.recorded() < frames && std::chrono::steady_clock::now() < deadline) {
    frame();
    std::this_thread::sleep_for(10ms);
  }
  EXPECT_TRUE(ear.wait_full(1s)) << panel.status_line();
  const auto& x = ear.samples(0);
  std::vector<double> logs;
  for (std::size_t at = 0; at + window <= x.size(); at += window) {
    double sum = 0.0;
    for (std::size_t i = at; i < at + window; ++i) sum += double(x[i]) * x[i];
    const double rms = std::sqrt(sum / static_cast<double>(window));
    EXPECT_GT(rms, 1e-5) << "silence in the recording at " << at;
    logs.push_back(std::log(std::max(rms, 1e-12)));
  }
  double mean = 0.0, square = 0.0;
  for (double l : logs) mean += l / static_cast<double>(logs.size());
  for (double l : logs) square += (l - mean) * (l - mean) / static_cast<double>(logs.size());
  return std::sqrt(square);
}

constexpr double kSweepSpread = 0.18, kConstantSpread = 0.15;

// The device the panel opened at start. On a loaded CI machine JACK once refused the panel's
// client there ("no device" in the status line, 1 run of many): it is opened again once, as a
// person would from the devices view, and the test says so; a second refusal fails it.
void ensure_device_open(Panel& panel, const PanelSetup& setup) {
  if (panel.audio().device()) return;
  ::testing::Test::RecordProperty("device_reopened", panel.error());
  const std::string again = panel.audio().open(*setup.device);
  ASSERT_TRUE(again.empty()) << "first: " << panel.error() << "; again: " << again;
}

StrokeChoice constant_250() {
  StrokeChoice c;
  c.kind = 0;
  c.speed_mm_s = 250.0f;
  return c;
}

TEST(PanelStroke, TheDesignViewPlaysTheStrokeChosenAfterItStartedAndAfterARelaunch) {
  nibrig::testing::JackServer server;
  const PanelSetup setup = testing::jack_design_setup("panel_stroke");
  PanelWindow window(testing::hidden_window());
  const std::string constant = rt::make_stroke(constant_250().request()).description;
  {
    Panel panel(setup);
    const auto frame = [&] {
      window.begin_frame();
      panel.draw();
      window.end_frame();
    };
    panel.show(View::design);
    testing::draw_until_design_settled(panel, frame, std::chrono::steady_clock::now() + 900s);
    ASSERT_TRUE(panel.design_view().ready()) << panel.design_view().error() << " " << panel.error();
    ensure_device_open(panel, setup);
    // Nothing plays until asked: a space or a grid arriving is not a request.
    EXPECT_FALSE(panel.audio().sounding().has_value()) << panel.status_line();

    ASSERT_EQ(panel.audio().stroke().kind, 1) << "the default stroke is the rig's sweep";
    panel.design_view().set_target(2);
    panel.design_view().set_design(0.0, 2.5);
    ASSERT_TRUE(panel.audio().sounding().has_value()) << panel.status_line();
    const std::string sweep = rt::make_stroke(panel.audio().stroke().request()).description;
    EXPECT_NE(panel.status_line().find(sweep), std::string::npos) << panel.status_line();
    const double spread_sweep = level_spread(panel, frame, 3.0);

    // What the design view's stroke widgets do when a person picks a constant 250 mm/s.
    panel.audio().stroke() = constant_250();
    panel.audio().stroke_changed();
    EXPECT_NE(panel.status_line().find(constant), std::string::npos) << panel.status_line();
    EXPECT_EQ(panel.status_line().find(sweep), std::string::npos) << panel.status_line();
    const double spread_constant = level_spread(panel, frame, 3.0);
    RecordProperty("spread_sweep", std::to_string(spread_sweep));
    RecordProperty("spread_constant", std::to_string(spread_constant));
    // Measured here over 3 s (a whole sweep period): 0.25-0.27 for the sweep, whose level follows
    // its speed from 17 to 250 mm/s; 0.08-0.10 for a constant speed, whose 300 ms windows differ
    // only by the texture's randomness. The bounds sit between the two, a third from each.
    EXPECT_GT(spread_sweep, kSweepSpread);
    EXPECT_LT(spread_constant, kConstantSpread);
    write_panel_settings(setup.space.parent_path() / "panel.json", panel_settings_of(panel));
  }
  // Relaunched with what it remembered: the design view plays the stroke the person left.
  Panel again(setup);
  apply_panel_settings(again, read_panel_settings(setup.space.parent_path() / "panel.json"));
  EXPECT_EQ(again.audio().stroke(), constant_250());
  const auto frame = [&] {
    window.begin_frame();
    again.draw();
    window.end_frame();
  };
  testing::draw_until_design_settled(again, frame, std::chrono::steady_clock::now() + 900s);
  ASSERT_TRUE(again.design_view().ready()) << again.design_view().error();
  ensure_device_open(again, setup);
  again.design_view().set_design(0.5, 2.5);
  EXPECT_EQ(again.audio().stroke_description(), constant) << again.status_line();
  EXPECT_LT(level_spread(again, frame, 3.0), kConstantSpread);
}

}  // namespace
}  // namespace nibrig::ui::panel
