// The design view on first use, in a real window: the grid is not in the cache, so a coarse grid
// (model/design coarse_axes) is solved first and the view is usable with it while the fine grid
// fills in; the progress says how many designs of how many and, once one is solved, the time left.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "model/design/design_response_grid.hpp"
#include "tests/ui/panel/design_cache.hpp"
#include "tests/ui/panel/panel_test_setup.hpp"
#include "ui/panel/panel.hpp"
#include "ui/panel/panel_window.hpp"

namespace nibrig::ui::panel {
namespace {

using namespace std::chrono_literals;

TEST(DesignView, ACoarseGridIsUsableWhileTheFineOneIsSolved) {
  const auto dir = std::filesystem::path(NIBRIG_TEST_BINARY_DIR) / "scratch" / "panel_design_first_use";
  std::filesystem::remove_all(dir);
  // The shared cache's forcing model (fitting it is not what this test is about), without its grids.
  const auto cache = dir / "cache";
  std::filesystem::create_directories(cache);
  for (const auto& entry : std::filesystem::directory_iterator(testing::shared_design_cache()))
    if (entry.path().filename().string().rfind("default_forcing-", 0) == 0)
      std::filesystem::copy_file(entry.path(), cache / entry.path().filename());
  ::setenv("NIBRIG_CACHE", cache.c_str(), 1);

  PanelWindow window(testing::hidden_window());
  PanelSetup setup = testing::design_setup(dir);
  setup.design.error_points = 1;
  Panel panel(setup);
  panel.show(View::design);
  auto& view = panel.design_view();
  const auto frame = [&] {
    window.begin_frame();
    panel.draw();
    window.end_frame();
    std::this_thread::sleep_for(5ms);
  };
  const auto deadline = std::chrono::steady_clock::now() + 900s;
  std::vector<std::string> messages;
  while (!view.ready() && std::chrono::steady_clock::now() < deadline) {
    frame();
    if (const auto m = view.progress_message(); !m.empty() && (messages.empty() || messages.back() != m))
      messages.push_back(m);
  }
  ASSERT_TRUE(view.ready()) << view.error();
  // 3 x 3 asked: its coarse grid keeps the ends of each axis, 2 x 2, and is in use first.
  ASSERT_TRUE(view.coarse());
  const auto fine = model::design::even_axes("vero", "DM85", 3, 0.001, 0.004, 3);
  EXPECT_EQ(view.grid()->axes.fractions, model::design::coarse_axes(fine).fractions);
  EXPECT_EQ(view.grid()->axes.tips_m, model::design::coarse_axes(fine).tips_m);
  view.set_playing(false);
  view.set_design(0.5, 2.5);  // inside the coarse grid: a prediction at once
  ASSERT_TRUE(view.predicted().has_value()) << view.error();

  while (view.coarse() && std::chrono::steady_clock::now() < deadline) {
    frame();
    if (const auto m = view.progress_message(); !m.empty() && messages.back() != m) messages.push_back(m);
  }
  ASSERT_FALSE(view.coarse()) << view.error();
  EXPECT_EQ(view.grid()->axes.fractions.size(), 3u);
  EXPECT_EQ(view.grid()->axes.tips_m.size(), 3u);
  // The progress named both steps with their counts (4 coarse, then the 5 others), and the time
  // left once a design of the step was solved.
  const auto said = [&](const std::string& text) {
    return std::any_of(messages.begin(), messages.end(), [&](const auto& m) { return m.find(text) != std::string::npos; });
  };
  EXPECT_TRUE(said("coarse grid: 0 of 4 designs solved")) << ::testing::PrintToString(messages);
  EXPECT_TRUE(said("fine grid: 0 of 5 designs solved")) << ::testing::PrintToString(messages);
  EXPECT_TRUE(said("s left")) << ::testing::PrintToString(messages);
  ::setenv("NIBRIG_CACHE", testing::shared_design_cache().c_str(), 1);
}

}  // namespace
}  // namespace nibrig::ui::panel
