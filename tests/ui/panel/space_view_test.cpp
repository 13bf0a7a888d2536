// The space view driven without a window: each tool is drawn where the space places it (equal units
// on both axes), hovering finds it, a click plays exactly it with the chosen stroke, shift-clicks
// build an A/B or triplet comparison of up to three, and the axes of a 3-D space can be chosen.
#include "ui/panel/space_view.hpp"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace nibrig::ui::panel
