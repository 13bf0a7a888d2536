// The CTest fixture of the design tests (tests/CMakeLists.txt): the panel's design view, opened in
// a hidden window on the coarse grid, solves the demo's forcing model and the grid into the shared
// cache (design_cache.hpp) with its progress shown, so that DesignView and DesignPlayback read
// them instead of solving them again.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>

#include "tests/ui/panel/design_cache.hpp"
#include "tests/ui/panel/panel_test_setup.hpp"
#include "tests/ui/panel/test_space.hpp"
#include "ui/panel/panel_window.hpp"

namespace nibrig::ui::panel {
namespace {

using namespace std::chrono_literals;

std::size_t design_grid_files(const std::filesystem::path& cache) {
  std::size_t n = 0;
  if (std::filesystem::exists(cache))
    for (const auto& entry : std::filesystem::directory_iterator(cache))
      n += entry.path().filename().string().starts_with("design-grid-");
  return n;
}

TEST(DesignCache, SolvesTheCoarseGridOnceForTheDesignTests) {
  testing::use_shared_design_cache();
  const auto dir = testing::shared_design_cache().parent_path() / "panel_design_cache_space";
  PanelWindow window(testing::hidden_window());
  Panel panel(testing::design_setup(dir));
  panel.show(View::design);
  auto& view = panel.design_view();
  bool progress_seen = false;
  const auto deadline = std::chrono::steady_clock::now() + 900s;
  while (!view.ready() && std::chrono::steady_clock::now() < deadline) {
    window.begin_frame();
    panel.draw();
    window.end_frame();
    progress_seen |= view.preparing();
    std::this_thread::sleep_for(5ms);
  }
  ASSERT_TRUE(view.ready()) << view.error() << " " << panel.error();
  EXPECT_TRUE(view.error().empty()) << view.error();
  EXPECT_TRUE(progress_seen) << "the grid was loaded without the view ever showing it prepare";
  // The grid the view loaded is the coarse one, and it is now in the shared cache.
  ASSERT_TRUE(view.predicted().has_value());
  EXPECT_GE(design_grid_files(testing::shared_design_cache()), 1u);
}

}  // namespace
}  // namespace nibrig::ui::panel
