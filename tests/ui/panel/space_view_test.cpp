// The space view driven without a window: each tool is drawn where the space places it (equal units
// on both axes), hovering finds it, a click plays exactly it, shift-clicks
// build an A/B or triplet comparison of up to three, and the axes of a 3-D space can be chosen.
#include "ui/panel/space_view.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "model/space/catalog_descriptors.hpp"
#include "ui/panel/panel_window.hpp"

#include <cmath>

#include "tests/ui/panel/headless_imgui.hpp"

namespace nibrig::ui::panel {
namespace {

SceneTool tool(const std::string& id, const std::string& surface, std::vector<double> at) {
  SceneTool t;
  t.choice = {id, surface};
  t.label = id + " on " + surface;
  t.kind = "printed";
  t.judged = true;
  t.region.mean = Eigen::Map<Eigen::VectorXd>(at.data(), static_cast<Eigen::Index>(at.size()));
  return t;
}

SpaceScene three_tools(std::size_t dims) {
  SpaceScene s;
  for (std::size_t d = 0; d < dims; ++d) s.axis_names.push_back("axis " + std::to_string(d + 1));
  s.tools = {tool("vero1", "office", {0.0, 0.0, 2.0}), tool("vero4", "office", {3.0, 1.0, -1.0}),
             tool("cryon", "note", {-2.0, 2.0, 0.5})};
  for (auto& t : s.tools) t.region.mean.conservativeResize(static_cast<Eigen::Index>(dims));
  s.surfaces = {"office", "note"};
  return s;
}

struct Played {
  std::vector<std::vector<ToolChoice>> calls;
};

TEST(SpaceView, DrawsEachToolWhereTheSpacePlacesItWithEqualUnitsOnBothAxes) {
  testing::HeadlessImGui imgui;
  SpaceView view(three_tools(2), {});
  imgui.frame([&] { view.draw(); });
  ASSERT_TRUE(view.frame().has_value());
  const ImVec2 a = *view.screen_position(0), b = *view.screen_position(1), c = *view.screen_position(2);
  for (const ImVec2& p : {a, b, c}) EXPECT_TRUE(view.frame()->contains(p));
  // (0,0) → (3,1): 3 units right and 1 up; equal units, so the pixel offsets are in ratio 3:1.
  EXPECT_GT(b.x, a.x);
  EXPECT_LT(b.y, a.y);  // up on the screen
  EXPECT_NEAR((b.x - a.x) / (a.y - b.y), 3.0, 0.02);
  // (0,0) → (-2,2): the same scale on both axes.
  EXPECT_NEAR((a.x - c.x) / (a.y - c.y), 1.0, 0.02);
}

TEST(SpaceView, AClickPlaysThatTool) {
  testing::HeadlessImGui imgui;
  Played played;
  SpaceView view(three_tools(2), [&](const std::vector<ToolChoice>& tools) { played.calls.push_back(tools); });
  imgui.frame([&] { view.draw(); });
  const ImVec2 p = *view.screen_position(1);
  imgui.mouse_to({p.x + 3.0f, p.y - 2.0f});  // near enough: within the 9 px a person aims with
  imgui.frame([&] { view.draw(); });
  ASSERT_EQ(view.hovered(), 1u);
  imgui.click({p.x + 3.0f, p.y - 2.0f}, [&] { view.draw(); });
  ASSERT_EQ(played.calls.size(), 1u);
  EXPECT_EQ(played.calls[0], (std::vector<ToolChoice>{{"vero4", "office"}}));
  // Away from every tool: nothing is hovered and a click plays nothing.
  const ImVec2 corner{view.frame()->origin().x + 2.0f, view.frame()->origin().y + view.frame()->size().y - 2.0f};
  imgui.click(corner, [&] { view.draw(); });
  EXPECT_FALSE(view.hovered().has_value());
  EXPECT_EQ(played.calls.size(), 1u);
}

TEST(SpaceView, ShiftClicksBuildAComparisonOfUpToThree) {
  testing::HeadlessImGui imgui;
  Played played;
  SpaceScene scene = three_tools(2);
  scene.tools.push_back(tool("stab", "note", {1.0, -2.0}));
  SpaceView view(scene, [&](const std::vector<ToolChoice>& tools) {
    played.calls.push_back(tools);
  });
  imgui.frame([&] { view.draw(); });
  imgui.click(*view.screen_position(0), [&] { view.draw(); });
  imgui.shift(true);
  imgui.click(*view.screen_position(2), [&] { view.draw(); });
  imgui.click(*view.screen_position(1), [&] { view.draw(); });
  imgui.click(*view.screen_position(3), [&] { view.draw(); });  // a fourth: the triplet is full
  imgui.shift(false);
  ASSERT_EQ(played.calls.size(), 4u);
  EXPECT_EQ(played.calls[1], (std::vector<ToolChoice>{{"vero1", "office"}, {"cryon", "note"}}));
  EXPECT_EQ(played.calls[2].size(), 3u);
  EXPECT_EQ(played.calls[3], played.calls[2]);
  EXPECT_EQ(view.chosen(), (std::vector<std::size_t>{0, 2, 1}));
}

TEST(SpaceView, TheAxesOfAThreeDimensionalSpaceCanBeChosen) {
  testing::HeadlessImGui imgui;
  SpaceView view(three_tools(3), {});
  view.set_axes(0, 2);
  imgui.frame([&] { view.draw(); });
  // On axis 3, vero1 (2.0) is above cryon (0.5), which is above vero4 (-1.0).
  const float y0 = view.screen_position(0)->y, y1 = view.screen_position(1)->y, y2 = view.screen_position(2)->y;
  EXPECT_LT(y0, y2);
  EXPECT_LT(y2, y1);
  EXPECT_NEAR((y1 - y0) / (y1 - y2), 3.0 / 1.5, 0.02);
}

TEST(SpaceView, AtTheSmallestWindowTheLegendStaysRightOfEveryTool) {
  // The window's minimum (PanelWindow::kMinWidth x kMinHeight), the side panel beside the plot.
  testing::HeadlessImGui imgui(static_cast<float>(PanelWindow::kMinWidth), static_cast<float>(PanelWindow::kMinHeight));
  SpaceScene scene = three_tools(2);
  scene.tools.push_back(tool("stab", "note", {6.0, 0.5}));  // the rightmost, where the legend was drawn
  SpaceView view(scene, {});
  imgui.frame([&] { view.draw(); });
  ASSERT_TRUE(view.frame().has_value());
  for (std::size_t i = 0; i < view.scene().tools.size(); ++i) {
    // A marker is 5 px across its centre at most.
    EXPECT_LT(view.screen_position(i)->x + 5.0f, view.legend_left()) << view.scene().tools[i].label;
  }
  EXPECT_LE(view.frame()->origin().x + view.frame()->size().x, view.legend_left());
}

TEST(SpaceView, TheTooltipSaysMuOnceThoughItIsADescriptorToo) {
  SceneTool t = tool("cryon", "office", {0.3, -1.0});
  t.mu = 0.3;
  t.descriptors = {{model::space::kFrictionDescriptor, 0.3}, {"log10_weighted_mean_vibration", -1.2}};
  const auto lines = tooltip_lines(t);
  const auto mu_lines = std::count_if(lines.begin(), lines.end(), [](const std::string& l) {
    return l.rfind("mu ", 0) == 0 || l.rfind(model::space::kFrictionDescriptor, 0) == 0;
  });
  EXPECT_EQ(mu_lines, 1);
  // The other descriptor is kept, with its value.
  EXPECT_NE(std::find(lines.begin(), lines.end(), "log10_weighted_mean_vibration -1.2"), lines.end());
  t.mu.reset();  // no mu of its own: the descriptor says it
  const auto without = tooltip_lines(t);
  EXPECT_NE(std::find(without.begin(), without.end(), "friction_mu 0.3"), without.end());
}

}  // namespace
}  // namespace nibrig::ui::panel
