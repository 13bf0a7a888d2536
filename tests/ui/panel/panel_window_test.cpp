// nibrig-panel in a real GLFW window on Xvfb (Mesa llvmpipe): every view renders into a PNG through
// the executable's --screenshot, each tool's point is on the screen where the space places it in
// its surface's colour, and the rig's waterfall shows the analysis's level at a known bin.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <map>
#include <string>
#include <thread>

#include "tests/ui/panel/panel_test_setup.hpp"
#include "tests/ui/panel/test_space.hpp"
#include "tests/ui/report/png_reader.hpp"
#include "ui/panel/panel.hpp"
#include "ui/panel/panel_window.hpp"
#include "ui/panel/rig_view.hpp"

namespace nibrig::ui::panel {
namespace {

std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::path(NIBRIG_TEST_BINARY_DIR) / "scratch" / ("panel_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

ui::report::Rgb rgb_of(ImU32 colour) {
  return {static_cast<std::uint8_t>(colour & 0xff), static_cast<std::uint8_t>((colour >> 8) & 0xff),
          static_cast<std::uint8_t>((colour >> 16) & 0xff)};
}

class EveryView : public ::testing::TestWithParam<const char*> {};

TEST_P(EveryView, RendersIntoAPictureThroughTheExecutable) {
  const auto dir = scratch(std::string("view_") + GetParam());
  const auto space = testing::write_small_space(dir);
  const auto png = dir / "view.png";
  // Its own cache, and the design view's coarse grid (3 × 3 designs, 4 mm mesh, 32 modes). The
  // design view is pictured while it prepares (--settle-timeout 0): solving it, three minutes under
  // the sanitizers, is what DesignView's own tests check.
  const std::string command = "NIBRIG_CACHE=" + (dir / "cache").string() + " " + NIBRIG_PANEL_BINARY + " --space " +
                              space.string() + " --screenshot " + png.string() + " --view " + GetParam() +
                              " --frames 3 --design-grid 3,3 --design-mesh 0.004 --design-modes 32" +
                              (std::string(GetParam()) == "design" ? " --settle-timeout 0" : "") + " > " +
                              (dir / "out.txt").string() + " 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const auto image = nibrig::test::decode_png(png);
  EXPECT_EQ(image.width, 1280);
  EXPECT_EQ(image.height, 800);
  // A picture of a view, not a blank window: beyond the background (the most common colour), the
  // tab bar, text, widgets and plots cover more than 4 % of it (the sparsest, the space with three
  // tools, covers 6 %; the tab bar and status line alone 3 %).
  std::map<std::uint32_t, std::size_t> count;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const auto c = image.at(x, y);
      ++count[c.r | (c.g << 8) | (c.b << 16)];
    }
  std::size_t background = 0;
  for (const auto& [colour, n] : count) background = std::max(background, n);
  const double drawn = 1.0 - static_cast<double>(background) / (image.width * image.height);
  RecordProperty("drawn_fraction", std::to_string(drawn));
  EXPECT_GT(drawn, 0.04) << "only " << 100 * drawn << " % of the picture differs from its background";
}

INSTANTIATE_TEST_SUITE_P(PanelWindow, EveryView, ::testing::Values("space", "design", "rig", "pad", "devices"));

// Draws the panel in a hidden window until `done` or 120 s, then one more frame into `png`.
void draw_until(PanelWindow& window, Panel& panel, const std::function<bool()>& done, const std::filesystem::path& png) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!done() && std::chrono::steady_clock::now() < deadline) {
    window.begin_frame();
    panel.draw();
    window.end_frame();
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  window.begin_frame();
  panel.draw();
  window.end_frame(png);
}

TEST(PanelWindow, EachToolIsDrawnWhereTheSpacePlacesItInItsSurfacesColour) {
  const auto dir = scratch("space_points");
  PanelWindow window(testing::hidden_window());
  PanelSetup setup;
  setup.space = testing::write_small_space(dir);
  Panel panel(setup);
  panel.show(View::space);
  int frames = 0;
  draw_until(window, panel, [&] { return panel.settled() && ++frames > 3; }, dir / "space.png");
  const auto& view = panel.space_view();
  ASSERT_EQ(view.scene().tools.size(), 3u);
  const auto image = nibrig::test::decode_png(dir / "space.png");
  const auto space = testing::small_space();
  for (std::size_t i = 0; i < 3; ++i) {
    const ImVec2 p = *view.screen_position(i);
    // Where the frame maps the file's coordinates...
    const ImVec2 expected = view.frame()->to_screen(space.coordinates(0, static_cast<Eigen::Index>(i)),
                                                    space.coordinates(1, static_cast<Eigen::Index>(i)));
    EXPECT_NEAR(p.x, expected.x, 0.01);
    EXPECT_NEAR(p.y, expected.y, 0.01);
    // ...the picture has a judged tool's filled marker in its surface's colour.
    const auto pixel = image.at(static_cast<int>(p.x), static_cast<int>(p.y));
    const auto want = rgb_of(view.surface_colour(view.scene().tools[i].choice.surface, 255));
    EXPECT_TRUE(nibrig::test::near(pixel, want, 3)) << "tool " << i << " at " << p.x << "," << p.y << ": (" << int(pixel.r)
                                            << "," << int(pixel.g) << "," << int(pixel.b) << ")";
  }
}

TEST(PanelWindow, TheRigsWaterfallShowsTheAnalysedLevelAtAKnownBin) {
  const auto dir = scratch("rig_waterfall");
  ::setenv("XDG_DATA_HOME", (dir / "data").c_str(), 1);  // the run's session goes here
  PanelWindow window(testing::hidden_window());
  PanelSetup setup;
  setup.start_rig = true;
  Panel panel(setup);
  panel.show(View::rig);
  auto& rig = panel.rig_view();
  draw_until(window, panel, [&] { return rig.measured() && rig.measured()->rows_pushed() >= 60; }, dir / "rig.png");
  ASSERT_NE(rig.measured(), nullptr) << rig.error();
  const auto image = nibrig::test::decode_png(dir / "rig.png");
  const auto waterfall = rig.waterfall_rect(0);  // named: clang 14 lambdas cannot capture bindings
  const ImVec2 min = waterfall.first, max = waterfall.second;
  const std::size_t bins = rig.measured()->bins();
  ASSERT_GT(bins, 30u);  // 0-500 Hz at 11.7 Hz
  // Newest row on top, each bin a column, nearest sampling: the pixel row 4 below the frame's edge
  // (which the frame's outline covers) shows the row whose texels hold its centre.
  const int py = static_cast<int>(min.y) + 4;
  const double offset_rows = (py + 0.5 - min.y) / (max.y - min.y) * static_cast<double>(rig.measured()->rows());
  const auto age = static_cast<std::size_t>(std::ceil(offset_rows) - 1);
  int matched = 0;
  for (std::size_t k : {3u, 10u, 20u, 30u}) {
    const float x = min.x + (static_cast<float>(k) + 0.5f) * (max.x - min.x) / static_cast<float>(bins);
    const auto pixel = image.at(static_cast<int>(x), py);
    const Rgba want = rig.measured()->colour_at(age, k);
    const bool same = nibrig::test::near(pixel, {want.r, want.g, want.b}, 2);
    matched += same;
    EXPECT_TRUE(same) << "bin " << k << ": (" << int(pixel.r) << "," << int(pixel.g) << "," << int(pixel.b)
                      << ") where the row " << age << " old has (" << int(want.r) << "," << int(want.g) << ","
                      << int(want.b) << ")";
  }
  EXPECT_EQ(matched, 4);
  rig.stop();
}

}  // namespace
}  // namespace nibrig::ui::panel
