// What a person waiting is told, in a real window: the first click on a tool with nothing in the
// user cache nor shipped with the build says that the stylus's modes are being solved (and kept),
// and its Cancel drops the sound being made; with the build's shipped modes nothing is solved; F12
// shows the frame times.
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <functional>
#include <thread>

#include "model/design/stylus_modes.hpp"
#include "model/io/user_cache.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/ui/panel/panel_test_setup.hpp"
#include "tests/ui/panel/test_space.hpp"
#include "ui/panel/panel.hpp"

namespace nibrig::ui::panel {
namespace {

struct WaitSession {
  PanelWindow window{testing::hidden_window()};
  Panel panel;
  explicit WaitSession(const PanelSetup& setup) : panel(setup) {}
  void frame(const std::function<void(ImGuiIO&)>& input = {}) {
    window.begin_frame(input);
    panel.draw();
    window.end_frame();
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  bool until(const std::function<bool()>& done) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (!done() && std::chrono::steady_clock::now() < deadline) frame();
    return done();
  }
};

TEST(PanelWaits, TheFirstClickSaysTheStylusModesAreSolvedAndCancelDropsIt) {
  const auto dir = std::filesystem::path(NIBRIG_TEST_BINARY_DIR) / "scratch" / "panel_waits";
  std::filesystem::remove_all(dir);
  ::setenv("NIBRIG_CACHE", (dir / "cache").c_str(), 1);  // empty: nothing solved yet
  // Nor shipped: the modes of a stylus the build did not solve (a lab's own template).
  const nibrig::test::ScopedEnvironment no_shipped_layer("NIBRIG_SHIPPED_CACHE", "");
  PanelSetup setup;
  setup.space = testing::write_small_space(dir);
  WaitSession s(setup);
  ASSERT_TRUE(s.until([&] { return s.panel.settled(); }));
  ASSERT_FALSE(std::filesystem::exists(model::design::stylus_modes_file({})));

  s.panel.audio().play({{"cryon", "office"}});
  ASSERT_TRUE(s.until([&] { return !s.panel.audio().making_message().empty(); }));
  EXPECT_NE(s.panel.audio().making_message().find("solving the stylus's modes"), std::string::npos)
      << s.panel.audio().making_message();
  s.panel.audio().cancel_making();
  s.frame();
  EXPECT_FALSE(s.panel.audio().making_sounds());
  EXPECT_TRUE(s.panel.audio().playing().empty());
  EXPECT_FALSE(s.panel.audio().sounding().has_value());

  // Asked again, it is made and sounds; the modes are kept, so a later click says nothing of them.
  s.panel.audio().play({{"cryon", "office"}});
  // Loaded and moved by the stroke (no device is open here, so nothing is heard: not "sounding").
  ASSERT_TRUE(s.until([&] { return !s.panel.audio().playing().empty(); })) << s.panel.audio().error();
  EXPECT_NE(s.panel.audio().stroke_description(), "stopped");
  EXPECT_FALSE(s.panel.audio().sounding().has_value()) << "sounding with no device open";
  EXPECT_TRUE(std::filesystem::exists(model::design::stylus_modes_file({})));

  // F12: the frame-time readout, and again to hide it.
  const auto press = [&](int key) {
    s.frame([&](ImGuiIO& io) { io.KeysDown[key] = true; });
    s.frame([&](ImGuiIO& io) { io.KeysDown[key] = false; });
  };
  EXPECT_FALSE(s.panel.frame_times_shown());
  press(GLFW_KEY_F12);
  EXPECT_TRUE(s.panel.frame_times_shown());
  press(GLFW_KEY_F12);
  EXPECT_FALSE(s.panel.frame_times_shown());
}

// The bundled stylus's modes, shipped with the build (model/design/bundled_defaults.hpp): the first
// click on a tool with an empty user cache solves nothing and writes nothing there.
TEST(PanelWaits, WithTheShippedModesTheFirstClickSolvesNothing) {
  if (model::io::shipped_cache_dir().empty())
    GTEST_SKIP() << "a build without the shipped defaults";
  const auto dir =
      std::filesystem::path(NIBRIG_TEST_BINARY_DIR) / "scratch" / "panel_waits_shipped";
  std::filesystem::remove_all(dir);
  const nibrig::test::ScopedCacheDir cache(dir / "cache");
  PanelSetup setup;
  setup.space = testing::write_small_space(dir);
  WaitSession s(setup);
  ASSERT_TRUE(s.until([&] { return s.panel.settled(); }));
  s.panel.audio().play({{"cryon", "office"}});
  bool solving_said = false;
  ASSERT_TRUE(s.until([&] {
    solving_said |=
        s.panel.audio().making_message().find("solving the stylus's modes") != std::string::npos;
    return !s.panel.audio().playing().empty();
  })) << s.panel.audio().error();
  EXPECT_FALSE(solving_said);
  EXPECT_FALSE(std::filesystem::exists(model::design::stylus_modes_file({})));
}

}  // namespace
}  // namespace nibrig::ui::panel
