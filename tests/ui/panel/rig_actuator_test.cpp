// The rig view plays the simulation on the actuator while the simulated rig runs, in a real window
// with a real JACK server: an independent libjack client hears what the actuator would (everything
// the panel sends to the device), turning the choice on makes it sound and turning it off silences it.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "tests/support/jack_server.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/ui/panel/windowed_panel.hpp"
#include "ui/panel/panel.hpp"
#include "ui/panel/rig_view.hpp"

namespace nibrig::ui::panel {
namespace {

using namespace std::chrono_literals;

// ... and while it plays, the status line says so; with the server dead, neither says "playing".
TEST(PanelRigActuator, TheSimulationPlaysOnTheActuatorWhileTheRigRunsUntilTurnedOff) {
  nibrig::testing::JackServer server;
  testing::WindowedPanel s(testing::small_space_on_jack("panel_rig_actuator"));
  // What reaches the actuator: the audition's port and, while it exists, the rig's player's.
  const auto actuator_rms = [&s](std::size_t frames) {
    return s.recorded_rms(frames, {"nibrig-panel:outport 0", "nibrig-panel-rig:outport 0"});
  };
  ASSERT_TRUE(s.panel.error().empty()) << s.panel.error();
  s.panel.show(View::rig);
  RigView& rig = s.panel.rig_view();
  rig.choice().kind = 0;
  rig.choice().tool = "cryon";
  rig.choice().surface = "office";
  rig.choice().profile = "sweep";
  rig.choice().seconds = 60.0f;  // outlasts the test: it is stopped at the end
  rig.choice().speedup = 1.0f;
  rig.choice().play_on_actuator = false;
  rig.start();
  // The capture runs once the tool's sound is made (the stylus meshed, or read from the cache).
  ASSERT_TRUE(s.frames_until([&] { return rig.progress() > 0.0 || !rig.running(); }, 300s));
  ASSERT_TRUE(rig.running()) << rig.error();
  EXPECT_FALSE(rig.actuator_playing());
  EXPECT_EQ(actuator_rms(4800), 0.0);  // the audition has nothing loaded: exact silence

  rig.choice().play_on_actuator = true;
  ASSERT_TRUE(s.frames_until([&] { return rig.actuator_playing() || !rig.actuator_state().empty(); }, 30s));
  ASSERT_TRUE(rig.actuator_playing()) << rig.actuator_state();
  EXPECT_NE(rig.actuator_state().find("playing cryon"), std::string::npos) << rig.actuator_state();
  // Half a second of the crayon's sweep (17-250 mm/s over 3 s) at the engine's default gain: the
  // actuator player's own test hears 0.014 of full scale at 30 mm/s, so 1e-3 lies ten times below
  // the quietest half second of the sweep, and is no silence (exact zero, above and below).
  EXPECT_GT(actuator_rms(24000), 1e-3);

  rig.choice().play_on_actuator = false;
  ASSERT_TRUE(s.frames_until([&] { return !rig.actuator_playing(); }, 30s));
  EXPECT_TRUE(rig.running());  // the rig goes on; only the actuator fell silent
  EXPECT_EQ(actuator_rms(4800), 0.0);  // the player's client is gone, the audition silent

  // On again: the status line says what the actuator plays, as the view does.
  rig.choice().play_on_actuator = true;
  ASSERT_TRUE(s.frames_until([&] { return rig.actuator_playing(); }, 30s)) << rig.actuator_state();
  EXPECT_NE(s.panel.status_line().find("| rig: playing cryon"), std::string::npos) << s.panel.status_line();
  // The server dies: neither the view nor the status line says "playing" any more.
  server.kill();
  ASSERT_TRUE(s.frames_until([&] { return rig.actuator_line().find("not heard") != std::string::npos; }, 20s))
      << rig.actuator_line();
  EXPECT_EQ(s.panel.status_line().find("playing cryon"), std::string::npos) << s.panel.status_line();
  EXPECT_NE(s.panel.status_line().find("| rig: the simulation is not heard"), std::string::npos)
      << s.panel.status_line();
  server.start();

  rig.stop();
  ASSERT_TRUE(s.frames_until([&] { return !rig.running(); }, 30s));
  EXPECT_TRUE(rig.error().empty()) << rig.error();
}

// With no device open the run still goes, and the view says why the actuator stays silent.
TEST(RigViewActuator, WithoutADeviceTheRigRunsAndSaysWhyTheActuatorIsSilent) {
  RigView view({}, {}, nibrig::test::scratch_dir("rig_view_no_device"));
  view.choice().tool = "cryon";
  view.choice().surface = "office";
  view.choice().profile = "sweep";
  view.choice().seconds = 2.0f;
  view.choice().speedup = 8.0f;
  view.choice().play_on_actuator = true;
  view.start();
  const auto deadline = std::chrono::steady_clock::now() + 300s;
  while (view.running() && view.actuator_state().empty() && std::chrono::steady_clock::now() < deadline) {
    view.take_feed();
    std::this_thread::sleep_for(10ms);
  }
  EXPECT_FALSE(view.actuator_playing());
  EXPECT_NE(view.actuator_state().find("no device is open"), std::string::npos) << view.actuator_state();
  while (view.running() && std::chrono::steady_clock::now() < deadline) std::this_thread::sleep_for(10ms);
  EXPECT_FALSE(view.running());
  view.take_feed();
  EXPECT_FALSE(view.speed_trace().empty());  // the rig ran its profile all the same
}

}  // namespace
}  // namespace nibrig::ui::panel
