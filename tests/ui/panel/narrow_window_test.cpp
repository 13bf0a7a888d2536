// At the panel's smallest window (800 × 500) the pad's row of controls ends inside the view: its
// last button, "Replay a stroke...", had run off the right edge, cut. The devices view's two
// columns hold their fields' labels and their lines (the labels "api (jack, alsa, pulse)" and
// "input device (by name)" and the actuator in use had been cut).
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "imgui.h"
#include "imgui_internal.h"
#include "tests/ui/panel/panel_test_setup.hpp"
#include "tests/ui/panel/test_space.hpp"
#include "ui/panel/pad_view.hpp"
#include "ui/panel/panel.hpp"

namespace nibrig::ui::panel {
namespace {

// The panel at its smallest window, on a small space, showing `view`; no pen looked for.
struct SmallestWindow {
  SmallestWindow(const char* scratch, View view)
      : window([] {
          WindowSettings settings = testing::hidden_window();
          settings.width = PanelWindow::kMinWidth;
          settings.height = PanelWindow::kMinHeight;
          return settings;
        }()),
        panel([&] {
          PanelSetup setup;
          setup.space = testing::write_small_space(nibrig::test::scratch_dir(scratch));
          return setup;
        }()) {
    panel.pad_view().pen().stop_looking();
    panel.show(view);
  }
  PanelWindow window;
  Panel panel;
};

TEST(NarrowWindow, ThePadsControlsEndInsideTheViewAtTheSmallestWindow) {
  SmallestWindow w("panel_narrow_window", View::pad);
  PanelWindow& window = w.window;
  Panel& panel = w.panel;
  float view_right = 0.0f;
  for (int i = 0; i < 5; ++i) {
    window.begin_frame();
    panel.draw();
    for (ImGuiWindow* w : GImGui->Windows)
      if (w->Active && std::string(w->Name).find("/view_") != std::string::npos) view_right = w->Rect().Max.x;
    window.end_frame();
  }
  ASSERT_EQ(panel.current(), View::pad);
  ASSERT_GT(view_right, 0.0f);
  const auto [low, high] = panel.pad_view().replay_button();
  const float label = ImGui::CalcTextSize("Replay a stroke...").x;
  EXPECT_GE(high.x - low.x, label) << "the button is narrower than its label";
  EXPECT_LE(high.x, view_right) << "the button ends at " << high.x << ", the view at " << view_right;
}

TEST(NarrowWindow, TheDevicesViewsColumnsHoldWhatTheyDrawAtTheSmallestWindow) {
  SmallestWindow w("panel_narrow_devices", View::devices);
  PanelWindow& window = w.window;
  Panel& panel = w.panel;
  // A column's content width is what its widest line needed in the frame before: the last frames
  // measure what the first ones laid out.
  std::vector<std::pair<std::string, float>> overrun;
  for (int i = 0; i < 6; ++i) {
    window.begin_frame();
    panel.draw();
    overrun.clear();
    for (ImGuiWindow* w : GImGui->Windows) {
      const std::string name = w->Name;
      if (!w->Active || (name.find("devices-choice") == std::string::npos && name.find("devices-listing") == std::string::npos))
        continue;
      overrun.emplace_back(name, w->ContentSize.x - w->ContentRegionRect.GetWidth());
    }
    window.end_frame();
  }
  ASSERT_EQ(panel.current(), View::devices);
  ASSERT_EQ(overrun.size(), 2u) << "both columns drawn";
  // One pixel: ImGui measures content in whole pixels, so a line that ends at the edge can measure
  // one over; a cut label is tens of pixels over (85 before the columns left room for them).
  for (const auto& [name, over] : overrun) EXPECT_LE(over, 1.0f) << name << " draws " << over << " px past its right edge";
}

}  // namespace
}  // namespace nibrig::ui::panel
