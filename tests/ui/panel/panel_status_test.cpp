// The status line says what is heard, on a real JACK server in a real window: "(sounding)" only
// while sound goes out (not on the pad with the button released, not with the server dead, when
// the line says LOST), and "Enter plays again" is what Enter does, also after another space was
// opened (which forgets the tools chosen in it, not the ones compared).
#include <gtest/gtest.h>

#include <GLFW/glfw3.h>

#include <chrono>
#include <string>

#include "tests/support/jack_server.hpp"
#include "tests/ui/panel/windowed_panel.hpp"
#include "ui/panel/pad_view.hpp"

namespace nibrig::ui::panel {
namespace {

using namespace std::chrono_literals;

bool status_says_sounding(const Panel& panel) {
  return panel.status_line().find("(sounding)") != std::string::npos;
}

TEST(PanelStatus, SoundingOnlyWhileHeardAndEnterPlaysAgainWhatTheLineOffers) {
  nibrig::testing::JackServer server;
  testing::WindowedPanel s(testing::small_space_on_jack("panel_status"));
  ASSERT_TRUE(s.frames_until([&] { return s.panel.settled(); }, 60s));
  s.panel.pad_view().pen().stop_looking();  // the pointer draws here, not a tablet

  s.click(*s.panel.space_view().screen_position(0));
  ASSERT_TRUE(s.frames_until([&] { return !s.panel.audio().playing().empty(); }, 300s)) << s.panel.audio().error();
  EXPECT_TRUE(status_says_sounding(s.panel)) << s.panel.status_line();

  // The pad: sounding while the button is down and moving, not once it is released.
  s.panel.show(View::pad);
  for (int f = 0; f < 3; ++f) s.frame();
  const ImVec2 centre{s.window.framebuffer_width() * 0.5f, s.window.framebuffer_height() * 0.5f};
  bool sounded_while_drawing = false;
  for (int f = 0; f < 30; ++f) {
    s.frame([&](ImGuiIO& io) {
      io.MousePos = {centre.x - 150.0f + 10.0f * static_cast<float>(f), centre.y};
      io.MouseDown[0] = f > 0;
    });
    if (f > 3 && s.panel.pad_view().drawing()) sounded_while_drawing |= status_says_sounding(s.panel);
  }
  EXPECT_TRUE(s.panel.pad_view().drawing()) << "the drag missed the pad's canvas";
  EXPECT_TRUE(sounded_while_drawing) << s.panel.status_line();
  for (int f = 0; f < 5; ++f) s.frame([&](ImGuiIO& io) { io.MousePos = centre, io.MouseDown[0] = false; });
  EXPECT_FALSE(s.panel.pad_view().drawing());
  EXPECT_FALSE(s.panel.audio().sounding().has_value());
  EXPECT_FALSE(status_says_sounding(s.panel)) << s.panel.status_line();

  // Stopped, another space opened: the line still offers the tools compared, and Enter plays them.
  s.panel.show(View::space);
  s.panel.audio().stop();
  s.panel.open_space(testing::write_small_space(std::filesystem::path(NIBRIG_TEST_BINARY_DIR) / "scratch" /
                                                "panel_status_other"));
  ASSERT_TRUE(s.frames_until([&] { return s.panel.current() == View::space && s.panel.settled(); }, 60s));
  EXPECT_TRUE(s.panel.space_view().chosen().empty());
  ASSERT_NE(s.panel.status_line().find("Enter plays again"), std::string::npos) << s.panel.status_line();
  // Stopped: the voices ring out, ten times below the sweep's quietest level heard below.
  EXPECT_LT(s.recorded_rms(4800), 1e-4);
  s.frame([&](ImGuiIO& io) { io.KeysDown[GLFW_KEY_ENTER] = true; });
  s.frame([&](ImGuiIO& io) { io.KeysDown[GLFW_KEY_ENTER] = false; });
  EXPECT_EQ(s.panel.audio().sounding(), (ToolChoice{"cryon", "office"})) << s.panel.status_line();
  EXPECT_TRUE(status_says_sounding(s.panel)) << s.panel.status_line();
  // The crayon's sweep at the default gain (PanelPlayback's threshold): heard, not just said.
  EXPECT_GT(s.recorded_rms(24000), 1e-3);

  // The server dies: LOST is said, and nothing is "sounding" while it is.
  server.kill();
  ASSERT_TRUE(s.frames_until([&] { return s.panel.status_line().find("LOST") != std::string::npos; }, 20s))
      << s.panel.status_line();
  EXPECT_FALSE(s.panel.audio().sounding().has_value());
  EXPECT_FALSE(status_says_sounding(s.panel)) << s.panel.status_line();
  server.start();
}

}  // namespace
}  // namespace nibrig::ui::panel
