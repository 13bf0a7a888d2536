// The frame-time readout (F12) sits where it covers no control: left of the space view's side
// panel (the stroke's controls, which it had covered) and above the status block, at the panel's
// smallest window and at the default one.
#include <gtest/gtest.h>

#include <string>

#include "imgui.h"
#include "imgui_internal.h"
#include "tests/ui/panel/panel_test_setup.hpp"
#include "tests/ui/panel/test_space.hpp"
#include "ui/panel/panel.hpp"

namespace nibrig::ui::panel {
namespace {

// The window whose name contains `part` (a child's name is its parent's, "/", its own, "_", an id).
ImGuiWindow* frame_times_window_named(const std::string& part) {
  for (ImGuiWindow* w : GImGui->Windows)
    if (w->Active && std::string(w->Name).find(part) != std::string::npos) return w;
  return nullptr;
}

// One window a test, as the suite's other window tests.
void frame_times_place_at(int width, int height) {
  const auto dir = nibrig::test::scratch_dir("panel_frame_times_place_" + std::to_string(width));
  WindowSettings settings = testing::hidden_window();
  settings.width = width;
  settings.height = height;
  PanelWindow window(settings);
  PanelSetup setup;
  setup.space = testing::write_small_space(dir);
  Panel panel(setup);
  panel.show_frame_times(true);
  for (int i = 0; i < 10; ++i) {  // the readout sizes itself to its text over the first frames
    window.begin_frame();
    panel.draw();
    ImGuiWindow* readout = frame_times_window_named("Frame times");
    ImGuiWindow* side = frame_times_window_named("/space-side_");
    ImGuiWindow* view = frame_times_window_named("/view_");
    if (i == 9) {
      ASSERT_NE(readout, nullptr);
      ASSERT_NE(side, nullptr);
      ASSERT_NE(view, nullptr);
      const ImRect r = readout->Rect(), s = side->Rect(), v = view->Rect();
      EXPECT_FALSE(r.Overlaps(s)) << "readout x " << r.Min.x << "-" << r.Max.x << ", side panel from " << s.Min.x;
      EXPECT_LE(r.Max.y, v.Max.y + 0.5f) << "the readout reaches into the status block";
      EXPECT_GE(r.Min.y, v.Min.y - 0.5f) << "the readout reaches above the view";
    }
    window.end_frame();
  }
}

TEST(FrameTimesPlace, AtTheSmallestWindowTheReadoutCoversNeitherTheStrokeControlsNorTheStatus) {
  frame_times_place_at(PanelWindow::kMinWidth, PanelWindow::kMinHeight);
}

TEST(FrameTimesPlace, AtTheDefaultWindowTheReadoutCoversNeitherTheStrokeControlsNorTheStatus) {
  frame_times_place_at(1280, 800);
}

}  // namespace
}  // namespace nibrig::ui::panel
