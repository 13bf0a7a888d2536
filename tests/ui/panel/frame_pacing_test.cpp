// What an idle panel does instead of drawing, in a real GLFW window under Xvfb: a frame whose draw
// lists are those on screen is not rendered again (unless a texture it shows changed), the pacing
// waits for input once nothing moves, and a job that ends wakes that wait at once.
#include "ui/panel/frame_pacing.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "imgui.h"
#include "tests/ui/panel/panel_test_setup.hpp"
#include "ui/panel/background_job.hpp"

namespace nibrig::ui::panel {
namespace {

void draw_text(PanelWindow& window, const char* text) {
  window.begin_frame();
  ImGui::Begin("pacing");
  ImGui::TextUnformatted(text);
  ImGui::End();
  window.end_frame();
}

TEST(FramePacing, AFrameThatChangedNothingIsNotRenderedAgain) {
  WindowSettings settings = testing::hidden_window();
  settings.skip_unchanged = true;
  PanelWindow window(settings);
  // ImGui sizes a new window over its first frames: the picture settles after a few.
  for (int i = 0; i < 4; ++i) draw_text(window, "one");
  const std::size_t rendered = window.frames_rendered(), skipped = window.frames_skipped();
  draw_text(window, "one");
  draw_text(window, "one");
  EXPECT_EQ(window.frames_rendered(), rendered);
  EXPECT_EQ(window.frames_skipped(), skipped + 2);
  draw_text(window, "two");
  EXPECT_EQ(window.frames_rendered(), rendered + 1);
  // A texture drawn by the same commands changed (a spectrogram's new rows): rendered.
  PanelWindow::contents_changed();
  draw_text(window, "two");
  EXPECT_EQ(window.frames_rendered(), rendered + 2);
  // A picture asked for is always rendered.
  window.begin_frame();
  ImGui::Begin("pacing");
  ImGui::TextUnformatted("two");
  ImGui::End();
  const auto png = std::filesystem::path(NIBRIG_TEST_BINARY_DIR) / "scratch" / "frame_pacing.png";
  window.end_frame(png);
  EXPECT_EQ(window.frames_rendered(), rendered + 3);
}

TEST(FramePacing, WaitsForInputOnceNothingMovesAndAFinishedJobWakesIt) {
  PanelWindow window(testing::hidden_window());
  FramePacing pacing;
  // Something moves: never a wait.
  for (int i = 0; i < 5; ++i) {
    pacing.before_frame(window, 0.0);
    EXPECT_FALSE(pacing.waited());
    draw_text(window, "moving");
  }
  // It stopped: the settle frames are drawn, then the pacing waits.
  for (int i = 0; i < FramePacing::kSettleFrames; ++i) {
    pacing.before_frame(window, 0.05);
    EXPECT_FALSE(pacing.waited()) << "settle frame " << i;
    draw_text(window, "still");
  }
  pacing.before_frame(window, 0.05);
  EXPECT_TRUE(pacing.waited());
  // A job ending on its own thread ends a long wait: true (woken), and the test does not sit out
  // the 30 s.
  BackgroundJob<int> job("a job", [](JobControl&) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    return 1;
  });
  EXPECT_TRUE(window.wait_events(30.0));
  EXPECT_TRUE(job.done());
}

}  // namespace
}  // namespace nibrig::ui::panel
