// The pad driven without a window: a pen dragged at a steady speed sends that speed to the engine
// (pixels per second × millimetres per pixel, after the 30 ms smoothing settles) and nothing once
// it is lifted.
#include "ui/panel/pad_view.hpp"

#include <gtest/gtest.h>

#include "tests/ui/panel/headless_imgui.hpp"

namespace nibrig::ui::panel {
namespace {

TEST(PadView, ADragAtASteadySpeedDrivesTheEngineAtThatSpeed) {
  testing::HeadlessImGui imgui;
  PanelAudio audio(model::design::ToolSoundOptions{});
  PadView pad(audio);
  pad.set_mm_per_pixel(0.25);
  imgui.frame([&] { pad.draw(); });
  // Somewhere inside the canvas, which starts below the tool row.
  ImVec2 at{300.0f, 300.0f};
  imgui.mouse_to(at);
  imgui.frame([&] { pad.draw(); });
  imgui.mouse_down(true);
  for (int frame = 0; frame < 40; ++frame) {  // 10 px per 1/60 s frame: 600 px/s
    at.x += 10.0f;
    imgui.mouse_to(at);
    imgui.frame([&] { pad.draw(); });
  }
  ASSERT_TRUE(pad.drawing());
  // 600 px/s × 0.25 mm/px = 150 mm/s; 40 frames are 22 time constants: settled to far below 1 %.
  EXPECT_NEAR(pad.speed_mm_s(), 150.0, 1.5);
  EXPECT_NEAR(pad.trace().back(), 150.0f, 1.5f);
  imgui.mouse_down(false);
  imgui.frame([&] { pad.draw(); });
  EXPECT_FALSE(pad.drawing());
  EXPECT_EQ(pad.speed_mm_s(), 0.0);
  EXPECT_TRUE(audio.error().empty()) << audio.error();
}

}  // namespace
}  // namespace nibrig::ui::panel
