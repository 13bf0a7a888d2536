// The pad driven without a window: a pen dragged at a steady speed sends that speed to the engine
// (pixels per second × millimetres per pixel) and nothing once it is lifted; a mouse that reports
// less often than the display draws sends no spikes; a pen held still on the pad stops.
#include "ui/panel/pad_view.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "model/io/drawing_trajectory_writer.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/ui/panel/headless_imgui.hpp"

namespace nibrig::ui::panel {
namespace {

// A pad at 0.25 mm a pixel, the mouse put down somewhere inside the canvas (below the tool row).
struct PenDown {
  testing::HeadlessImGui imgui;
  PanelAudio audio{model::design::ToolSoundOptions{}};
  PadView pad{audio};
  ImVec2 at{300.0f, 300.0f};
  PenDown() {
    pad.pen().stop_looking();  // the mouse's tests: no tablet search
    pad.set_mm_per_pixel(0.25);
    imgui.frame([&] { pad.draw(); });
    imgui.mouse_to(at);
    imgui.frame([&] { pad.draw(); });
    imgui.mouse_down(true);
  }
};

TEST(PadView, ADragAtASteadySpeedDrivesTheEngineAtThatSpeed) {
  PenDown p;  // named, not bound: clang 14 lambdas cannot capture structured bindings
  auto& imgui = p.imgui;
  auto& audio = p.audio;
  auto& pad = p.pad;
  auto& at = p.at;
  for (int frame = 0; frame < 40; ++frame) {  // 10 px per 1/60 s frame: 600 px/s
    at.x += 10.0f;
    imgui.mouse_to(at);
    imgui.frame([&] { pad.draw(); });
  }
  ASSERT_TRUE(pad.drawing());
  // 600 px/s × 0.25 mm/px = 150 mm/s, from the pointer's own steps: within float rounding.
  EXPECT_NEAR(pad.speed_mm_s(), 150.0, 1.5);
  EXPECT_NEAR(pad.trace().back(), 150.0f, 1.5f);
  imgui.mouse_down(false);
  imgui.frame([&] { pad.draw(); });
  EXPECT_FALSE(pad.drawing());
  EXPECT_EQ(pad.speed_mm_s(), 0.0);
  EXPECT_TRUE(audio.error().empty()) << audio.error();
}

TEST(PadView, AMouseSlowerThanTheDisplaySendsASteadySpeedWithoutSpikes) {
  PenDown p;  // named, not bound: clang 14 lambdas cannot capture structured bindings
  auto& imgui = p.imgui;
  auto& pad = p.pad;
  auto& at = p.at;
  // 600 px/s again, but the pointer reports on two frames of three (40 Hz on a 60 Hz display):
  // 10 px after one frame, 20 px after two. A difference per frame read 0 and 1200 px/s in turn.
  std::vector<double> sent;
  for (int frame = 1; frame <= 60; ++frame) {
    if (frame % 3 != 0) {
      at.x += frame % 3 == 1 ? 20.0f : 10.0f;
      imgui.mouse_to(at);
    }
    imgui.frame([&] { pad.draw(); });
    if (frame > 6) sent.push_back(pad.speed_mm_s());  // after the first two events
  }
  const auto [low, high] = std::minmax_element(sent.begin(), sent.end());
  // Two intervals always span three frames here (30 px in 1/20 s): exactly 150 mm/s, within
  // the float rounding of the positions and times.
  EXPECT_NEAR(*low, 150.0, 1.5);
  EXPECT_NEAR(*high, 150.0, 1.5);
  // Held still: within 50 ms (3 frames at 60 Hz plus one) the speed is 0, the pen still down.
  for (int frame = 0; frame < 5; ++frame) imgui.frame([&] { pad.draw(); });
  EXPECT_TRUE(pad.drawing());
  EXPECT_EQ(pad.speed_mm_s(), 0.0);
}

// A stroke recorded in the drawing format (as `audition --pen --record` keeps one) replays as the
// pad's input: its speed and force reach the engine while it plays, then nothing.
TEST(PadView, ARecordedStrokeReplaysAsThePadsInput) {
  const auto file = nibrig::test::scratch_dir("pad_replay") / model::io::drawing_file_name("cryon", "office", "pad");
  {
    model::io::DrawingTrajectoryWriter writer(file, model::io::WallClockOrigin::now());
    for (int i = 0; i <= 133; ++i) {  // one second at 133 Hz, 80 mm/s along x under 1.5 N
      model::io::DrawingFrame f;
      f.time_s = 100.0 + i / 133.0;
      f.x_m = 0.02 + 0.080 * i / 133.0;
      f.y_m = 0.05;
      f.normal_force_N = 1.5;
      f.touching = true;
      writer.append(f);
    }
  }
  testing::HeadlessImGui imgui;
  PanelAudio audio{model::design::ToolSoundOptions{}};
  PadView pad{audio};
  pad.pen().stop_looking();
  ASSERT_EQ(pad.replay(file), "");
  std::vector<double> speeds, forces;
  for (int frame = 0; frame < 40; ++frame) {  // 2/3 s of the pad's clock (1/60 s a frame)
    imgui.frame([&] { pad.draw(); });
    if (frame > 5) {
      speeds.push_back(pad.speed_mm_s());
      forces.push_back(pad.force_n());
    }
  }
  EXPECT_TRUE(pad.replaying());
  EXPECT_TRUE(pad.drawing());
  // The reader's speed: 80 mm/s from the rows' 0.6 mm steps (to the format's 0.0001 mm) times its
  // frame-rate estimate from millisecond stamps: within 1 %.
  for (double v : speeds) EXPECT_NEAR(v, 80.0, 0.8);
  for (double f : forces) EXPECT_NEAR(f, 1.5, 1e-4);  // written to 0.0001 N
  for (int frame = 0; frame < 40; ++frame) imgui.frame([&] { pad.draw(); });
  EXPECT_FALSE(pad.replaying());
  EXPECT_FALSE(pad.drawing());
  EXPECT_EQ(pad.speed_mm_s(), 0.0);
  EXPECT_EQ(pad.force_n(), 0.0);
  EXPECT_NE(pad.replay(file.parent_path() / "missing_office_pad.csv"), "");  // the reader's refusal, shown
}

}  // namespace
}  // namespace nibrig::ui::panel
