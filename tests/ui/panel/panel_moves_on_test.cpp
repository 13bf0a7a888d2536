// What the panel keeps once the person moves on: an error stays in the line while its view is
// shown and leaves it when another view is (a catalog's error had stayed 11 minutes through a rig
// run, the pad, a study and a search); a space file that failed to open is neither remembered for
// the next start nor left as an empty view: with nothing shown, the default space is computed.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <thread>

#include "tests/ui/panel/panel_test_setup.hpp"
#include "tests/ui/panel/test_space.hpp"
#include "ui/panel/panel.hpp"
#include "ui/panel/panel_settings.hpp"

namespace nibrig::ui::panel {
namespace {

struct MovesOn {
  PanelWindow window{testing::hidden_window()};
  Panel panel;
  explicit MovesOn(const PanelSetup& setup) : panel(setup) {}
  void frames(int n) {
    for (int i = 0; i < n; ++i) {
      window.begin_frame();
      panel.draw();
      window.end_frame();
    }
  }
  bool until(const std::function<bool()>& done, std::chrono::seconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (!done() && std::chrono::steady_clock::now() < deadline) {
      frames(1);
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return done();
  }
};

std::filesystem::path moves_on_dir(const char* name) {
  const auto dir = std::filesystem::path(NIBRIG_TEST_BINARY_DIR) / "scratch" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

TEST(PanelMovesOn, AnErrorLeavesTheLineWhenAnotherViewIsShownAndIsKeptInTheHistory) {
  const auto dir = moves_on_dir("panel_moves_on_error");
  PanelSetup setup;
  setup.space = testing::write_small_space(dir);
  MovesOn s(setup);
  ASSERT_TRUE(s.until([&] { return s.panel.settled(); }, std::chrono::seconds(60)));
  s.panel.open_space(dir / "no_such_space.json");
  ASSERT_TRUE(s.until([&] { return !s.panel.error().empty(); }, std::chrono::seconds(60)));
  const std::string failed = s.panel.error();
  s.frames(20);
  EXPECT_EQ(s.panel.error(), failed) << "it stays while its view is shown";

  s.panel.show(View::pad);
  s.frames(3);
  EXPECT_EQ(s.panel.current(), View::pad);
  EXPECT_EQ(s.panel.error(), "");
  ASSERT_FALSE(s.panel.errors().history().empty());
  EXPECT_EQ(s.panel.errors().history().front().text, failed);

  // An error of the pad's stays on the pad, and goes when the person goes back to the space.
  s.panel.set_error("the pad's problem");
  s.frames(20);
  EXPECT_EQ(s.panel.error(), "the pad's problem");
  s.panel.show(View::space);
  s.frames(3);
  EXPECT_EQ(s.panel.error(), "");
}

// A second window in one test process sometimes fails to open on Xvfb ("Failed to open display"):
// each test opens one.
TEST(PanelMovesOn, ASpaceThatFailedToOpenIsNotRemembered) {
  const auto dir = moves_on_dir("panel_moves_on_space");
  const auto broken = dir / "broken_space.json";
  std::ofstream(broken) << "{ this is not a space";
  PanelSetup setup;
  setup.space = testing::write_small_space(dir);
  MovesOn s(setup);
  ASSERT_TRUE(s.until([&] { return s.panel.settled(); }, std::chrono::seconds(60)));
  const std::size_t shown = s.panel.space_view().scene().tools.size();
  ASSERT_GT(shown, 0u);
  s.panel.open_space(broken);
  ASSERT_TRUE(s.until([&] { return !s.panel.busy() && !s.panel.error().empty(); }, std::chrono::seconds(60)));
  EXPECT_NE(s.panel.error().find("broken_space.json"), std::string::npos) << s.panel.error();
  // The space shown is what is remembered for the next start, not the file that failed.
  EXPECT_EQ(s.panel.space_file(), setup.space);
  EXPECT_EQ(panel_settings_of(s.panel).space, setup.space);
  EXPECT_EQ(s.panel.space_view().scene().tools.size(), shown);
}

// Started on a broken file (a settings file from before, a command line): the error says so, and
// the default space is computed rather than an empty view waiting for nothing.
TEST(PanelMovesOn, StartedOnASpaceThatFailsTheDefaultIsComputed) {
  const auto dir = moves_on_dir("panel_moves_on_start");
  const auto broken = dir / "broken_space.json";
  std::ofstream(broken) << "{ this is not a space";
  PanelSetup setup;
  setup.space = broken;
  MovesOn s(setup);
  ASSERT_TRUE(s.until([&] { return !s.panel.error().empty(); }, std::chrono::seconds(60)));
  EXPECT_NE(s.panel.error().find("broken_space.json"), std::string::npos) << s.panel.error();
  // Computing it, or (read from the cache) done already: either way not an empty view idling.
  ASSERT_TRUE(s.panel.busy() || !s.panel.space_view().scene().tools.empty()) << "nothing is computed";
  EXPECT_EQ(s.panel.space_file(), std::filesystem::path());
  // Read from the tests' cache once computed (about a second); computed afresh, a few minutes.
  ASSERT_TRUE(s.until([&] { return !s.panel.space_view().scene().tools.empty(); }, std::chrono::seconds(400)))
      << s.panel.error();
  EXPECT_NE(s.panel.error().find("the default space is shown instead"), std::string::npos) << s.panel.error();
  EXPECT_EQ(panel_settings_of(s.panel).space, std::filesystem::path());
}

}  // namespace
}  // namespace nibrig::ui::panel
