// The rig view with a USB rig plugged in: the controller emulated through umockdev
// (tests/rig/usb/emulated_rig.hpp), the accelerometer a sine played into a real JACK server's
// graph, the view drawn in a real GLFW window on Xvfb. What a person at the panel checks: the
// speed trace follows the profile the controller was given, the measured spectrogram shows the
// accelerometer's tone where it is, the comparison table fills, and pulling the cable ends the run
// with the reason shown and the session kept. The view opens the rig, then meshes the simulated
// tool for ~20 s: longer than the accelerometer's ring holds, which once left the capture's speed
// at 0 throughout (AccelerometerInput now counts what the full ring dropped).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <string>
#include <thread>

#include "model/io/rig_session.hpp"
#include "rig/speed_profile.hpp"
#include "tests/rig/jack_feeder.hpp"
#include "tests/rig/usb/emulated_rig.hpp"
#include "tests/support/jack_server.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/ui/panel/panel_test_setup.hpp"
#include "ui/panel/panel_window.hpp"
#include "ui/panel/rig_view.hpp"

namespace nibrig::ui::panel {
namespace {

using namespace std::chrono_literals;

constexpr double kToneHz = 200.0;  // inside the waterfalls' 0-500 Hz, far from their ends

// The rig view alone in the window, as the panel lays out a view.
void frame(PanelWindow& window, RigView& view) {
  window.begin_frame();
  ImGui::SetNextWindowPos({0, 0});
  ImGui::SetNextWindowSize(ImGui::GetIO().DisplaySize);
  ImGui::Begin("rig", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings);
  view.draw();
  ImGui::End();
  window.end_frame();
}

// Frames at a screen's pace until `done` or the deadline; the feeder is patched into the rig's
// input as soon as its port exists (the accelerometer's stream opens inside the run).
// A run's end is taken up by the frame after it: frames_until draws that one too.
bool frames_until(PanelWindow& window, RigView& view, rig::testing::JackFeeder& feeder,
                  const std::function<bool()>& done, std::chrono::seconds limit) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  bool patched = false;
  while (std::chrono::steady_clock::now() < deadline) {
    frame(window, view);
    if (!patched) patched = feeder.connect("nibrig-rig-input:inport 0");
    if (done()) {
      frame(window, view);
      return true;
    }
    std::this_thread::sleep_for(10ms);
  }
  return false;
}

std::size_t nearest_bin(const std::vector<double>& frequencies_hz, double f) {
  std::size_t best = 0;
  for (std::size_t k = 0; k < frequencies_hz.size(); ++k)
    if (std::abs(frequencies_hz[k] - f) < std::abs(frequencies_hz[best] - f)) best = k;
  return best;
}

TEST(RigViewUsb, RunsTheControllerShowsWhatItMeasuresAndSaysWhenItIsUnplugged) {
  nibrig::testing::JackServer server;
  rig::usb::testing::Testbed testbed;
  rig::usb::testing::EmulatedRig device(testbed.get(), rig::usb::testing::EmulatedRigConfig{});
  rig::testing::JackFeeder feeder("accelerometer", 0.1, kToneHz);
  const auto sessions = nibrig::test::scratch_dir("rig_view_usb");
  PanelWindow window(testing::hidden_window());
  RigView view({}, {}, sessions);
  RigChoice& c = view.choice();
  c.kind = 2;  // the USB controller
  c.usb_serial = "NIB-0001";
  c.input_api = "jack";
  c.profile = "sweep";
  c.seconds = 6.0f;  // two of the paper's 3 s sweeps

  // A whole run.
  view.start();
  ASSERT_TRUE(frames_until(window, view, feeder, [&] { return !view.running(); }, 120s)) << "the run never ended";
  ASSERT_EQ(view.error(), "");
  EXPECT_NE(view.finished().find("session"), std::string::npos) << view.finished();
  EXPECT_EQ(view.finished().find("unplugged"), std::string::npos) << view.finished();

  // The speed trace: the controller's encoder following the sweep (its motor lags by 50 ms, so the
  // top of each sweep is reached to within a few percent).
  const rig::SpeedProfile sweep = rig::profile_named("sweep", 6.0);
  double top_mm_s = 0.0;
  for (double t = 0.0; t < 6.0; t += 0.001) top_mm_s = std::max(top_mm_s, sweep.speed_at(t) * 1e3);
  ASSERT_FALSE(view.speed_trace().empty());
  const double traced_top = *std::max_element(view.speed_trace().begin(), view.speed_trace().end());
  EXPECT_NEAR(traced_top, top_mm_s, 0.05 * top_mm_s);

  // The measured spectrogram: the tone's bin is the brightest of the newest rows. Viridis's green
  // rises with the level, so the tone's column is greener than a bin an octave away, which holds
  // only the silence of the server's capture port.
  ASSERT_NE(view.measured(), nullptr);
  ASSERT_GT(view.measured()->rows_pushed(), 100u);  // 6 s at ~21 ms per row
  const auto& hz = view.shown_frequencies();
  const std::size_t tone = nearest_bin(hz, kToneHz), octave = nearest_bin(hz, 2 * kToneHz);
  for (std::size_t age : {5u, 20u, 60u}) {
    const auto at_tone = view.measured()->colour_at(age, tone);
    const auto away = view.measured()->colour_at(age, octave);
    EXPECT_GT(at_tone.g, away.g + 60) << "row " << age << " old: tone bin " << hz[tone] << " Hz, octave bin "
                                      << hz[octave] << " Hz";
  }
  // The live comparison's table: measured against simulated per speed.
  ASSERT_TRUE(view.table().has_value());
  EXPECT_GT(view.table()->rows_analysed, 100u);
  EXPECT_FALSE(view.table()->bins.empty());

  // Pulled out mid-run: the run ends, the view says why, and the session so far is on disk.
  view.start();
  ASSERT_TRUE(frames_until(window, view, feeder, [&] { return view.measured() && view.measured()->rows_pushed() >= 20; },
                           60s))
      << view.error();
  device.unplug();
  ASSERT_TRUE(frames_until(window, view, feeder, [&] { return !view.running(); }, 60s)) << "the run went on unplugged";
  const std::string said = view.error() + view.finished();
  EXPECT_NE(said.find("unplugged"), std::string::npos) << said;
  std::size_t kept = 0;
  for (const auto& entry : std::filesystem::directory_iterator(sessions))
    if (std::filesystem::exists(entry.path() / model::io::kSessionJson)) ++kept;
  EXPECT_EQ(kept, 2u) << "both runs' sessions";
}

}  // namespace
}  // namespace nibrig::ui::panel
