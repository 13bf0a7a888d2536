// A panel in a real (hidden) window on Xvfb, driven frame by frame, and what it sends to a JACK
// device as an independent libjack client hears it: the fixture of the tests that listen.
#pragma once

#include <chrono>
#include <filesystem>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "tests/playback/jack_recorder.hpp"
#include "tests/ui/panel/panel_test_setup.hpp"
#include "tests/ui/panel/test_space.hpp"
#include "ui/panel/panel.hpp"
#include "ui/panel/panel_window.hpp"

namespace nibrig::ui::panel::testing {

// A panel opening a small space (written under the build tree's scratch/`name`) on the test JACK
// server's device, 64 frames a period.
inline PanelSetup small_space_on_jack(const std::string& name) {
  const auto dir = std::filesystem::path(NIBRIG_TEST_BINARY_DIR) / "scratch" / name;
  std::filesystem::remove_all(dir);
  PanelSetup setup;
  setup.space = write_small_space(dir);
  setup.device = DeviceRequest{"jack", "system", 1, 64};
  return setup;
}

struct WindowedPanel {
  PanelWindow window;
  Panel panel;
  explicit WindowedPanel(const PanelSetup& setup) : window(hidden_window()), panel(setup) {}

  void frame(const std::function<void(ImGuiIO&)>& input = {}) {
    window.begin_frame(input);
    panel.draw();
    window.end_frame();
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  // Frames until `done` (true) or the timeout (false).
  bool frames_until(const std::function<bool()>& done, std::chrono::seconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (!done()) {
      if (std::chrono::steady_clock::now() > deadline) return false;
      frame();
    }
    return true;
  }
  void click(ImVec2 at) {
    frame([&](ImGuiIO& io) { io.MousePos = at; });
    frame([&](ImGuiIO& io) { io.MousePos = at, io.MouseDown[0] = true; });
    frame([&](ImGuiIO& io) { io.MousePos = at, io.MouseDown[0] = false; });
  }
  // RMS of `frames` recorded by a bare libjack client from `ports` mixed into one input, as a
  // device's own port mixes them, the panel drawing on. The first port must exist; the others
  // are connected when they do.
  double recorded_rms(std::size_t frames,
                      std::initializer_list<std::string> ports = {"nibrig-panel:outport 0"}) {
    playback::testing::JackRecorder ear("ear", 1, frames);
    bool first = true;
    for (const auto& port : ports) {
      const bool connected = ear.connect(port, 0);
      if (first) {
        EXPECT_TRUE(connected) << port;
      }
      first = false;
    }
    ear.start();
    EXPECT_TRUE(frames_until([&] { return ear.recorded() >= frames; }, std::chrono::seconds(30)))
        << ear.recorded() << " recorded";
    double sum = 0.0;
    for (float s : ear.samples(0)) sum += double(s) * s;
    return std::sqrt(sum / static_cast<double>(frames));
  }
};

}  // namespace nibrig::ui::panel::testing
