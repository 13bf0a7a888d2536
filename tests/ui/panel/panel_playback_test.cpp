// A scripted session in a real window with a real JACK server: the panel opens on the server's
// device, a click on a tool's point makes its sound and plays it (an independent libjack client
// records it), and when the server dies the panel says so and plays again once it is back.
#include <gtest/gtest.h>

#include <chrono>

#include "tests/support/jack_server.hpp"
#include "tests/ui/panel/windowed_panel.hpp"
#include "ui/panel/panel.hpp"

namespace nibrig::ui::panel {
namespace {

using namespace std::chrono_literals;

TEST(PanelPlayback, AClickedToolPlaysOnTheDeviceAndPlaysAgainAfterTheServerCameBack) {
  nibrig::testing::JackServer server;
  testing::WindowedPanel s(testing::small_space_on_jack("panel_playback"));
  ASSERT_TRUE(s.panel.error().empty()) << s.panel.error();
  ASSERT_TRUE(s.frames_until([&] { return s.panel.settled(); }, 60s));
  EXPECT_EQ(s.panel.status_line().rfind("jack system | ", 0), 0u) << s.panel.status_line();
  EXPECT_FALSE(s.panel.audio().sounding().has_value());
  EXPECT_EQ(s.recorded_rms(4800), 0.0);  // nothing loaded: exact silence

  // A click on cryon on office paper: its sound is made (the stylus meshed) and it plays the sweep.
  s.click(*s.panel.space_view().screen_position(0));
  ASSERT_TRUE(s.frames_until([&] { return !s.panel.audio().playing().empty(); }, 300s)) << s.panel.audio().error();
  EXPECT_EQ(s.panel.audio().playing()[0], (ToolChoice{"cryon", "office"}));
  EXPECT_NE(s.panel.status_line().find("A: cryon"), std::string::npos) << s.panel.status_line();
  // The one sounding is marked where a person looks: the status line and the space view.
  EXPECT_EQ(s.panel.audio().sounding(), (ToolChoice{"cryon", "office"}));
  s.frame();
  EXPECT_EQ(s.panel.space_view().sounding(), (ToolChoice{"cryon", "office"}));
  // The crayon's sweep at the default gain: well above 1e-3 of full scale (LiveAudition's test).
  const double playing = s.recorded_rms(24000);
  EXPECT_GT(playing, 1e-3);

  // The server dies: the panel says the device is lost, and plays again when it is back.
  server.kill();
  ASSERT_TRUE(s.frames_until([&] { return s.panel.status_line().find("LOST") != std::string::npos; }, 20s))
      << s.panel.status_line();
  server.start();
  ASSERT_TRUE(s.frames_until(
      [&] { return s.panel.audio().audition().output_stats()->reconnects >= 1 &&
                   s.panel.status_line().find("LOST") == std::string::npos; },
      30s))
      << s.panel.status_line();
  EXPECT_GT(s.recorded_rms(24000), 1e-3);
}

}  // namespace
}  // namespace nibrig::ui::panel
