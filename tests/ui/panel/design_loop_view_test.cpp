// A design loop's rounds in the panel's Design view, in a real hidden window on Xvfb: opened from
// its folder (as `nibrig-panel --loop` and File > Open design loop do), every round's predicted and
// measured place as the folder keeps them, the round awaiting its print shown as the next print,
// followed as the loop goes on elsewhere; a folder holding no loop is named in the error line and
// leaves the loop shown.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "model/design/loop_folder.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/ui/panel/windowed_panel.hpp"

namespace nibrig::ui::panel {
namespace {

namespace design = model::design;
using ::testing::HasSubstr;

design::LoopRoundRecord loop_view_round(int number, double x, double y, bool measured) {
  design::LoopRoundRecord r;
  r.number = number;
  r.design = design::parse_design_point("vero:0.5,DM85:0.5,tip=" + std::to_string(number) + "mm");
  r.predicted_distance = 1.5 / number;
  r.predicted_distance_sd = 0.2;
  r.chance_within = 0.3;
  r.predicted_position = Eigen::Vector2d(x, y);
  if (measured)
    r.measured = design::LoopMeasuredRecord{1.2 / number, 0.1, Eigen::Vector2d(x + 0.01, y - 0.02),
                                            Eigen::Vector2d(0.2, -1.2)};
  return r;
}

TEST(PanelDesignLoop, ALoopsRoundsAreShownInTheDesignViewWithItsNextPrint) {
  const auto dir = nibrig::test::scratch_dir("panel_design_loop");
  const auto loop = dir / "loop";
  design::LoopRequest request;
  request.target = "cryon/office";
  request.surface = "office";
  request.space_file = dir / "descriptor_space.json";
  design::write_loop_request(loop, request);
  design::write_round(loop, loop_view_round(1, 0.21, -1.15, true));
  design::write_round(loop, loop_view_round(2, 0.24, -1.18, true));
  design::write_round(loop, loop_view_round(3, 0.25, -1.19, false));

  PanelSetup setup;
  setup.space = testing::write_descriptor_space(dir);
  setup.design = testing::coarse_design();
  setup.loop = loop;
  testing::WindowedPanel p(setup);
  ASSERT_TRUE(p.frames_until([&] { return !p.panel.busy(); }, std::chrono::seconds(120)));
  for (int k = 0; k < 3; ++k) p.frame();  // the view drawn with the loop over its space
  EXPECT_TRUE(p.panel.error().empty()) << p.panel.error();
  EXPECT_EQ(p.panel.current(), View::design);
  const auto& shown = p.panel.design_view().loop();
  ASSERT_TRUE(shown.has_value());
  ASSERT_EQ(shown->rounds().size(), 3u);
  ASSERT_NE(shown->next_print(), nullptr);
  EXPECT_EQ(shown->next_print()->number, 3);
  // As kept: JSON's shortest round-trip decimals give the doubles back.
  EXPECT_EQ(shown->rounds()[1].measured->position, Eigen::Vector2d(0.24 + 0.01, -1.18 - 0.02));
  EXPECT_EQ(shown->rounds()[2].predicted_position, Eigen::Vector2d(0.25, -1.19));

  // The loop goes on elsewhere (the command, Python): round 3 measured, round 4 proposed. The
  // view follows within a few of its looks.
  design::write_round(loop, loop_view_round(3, 0.25, -1.19, true));
  design::write_round(loop, loop_view_round(4, 0.26, -1.20, false));
  ASSERT_TRUE(p.frames_until([&] { return p.panel.design_view().loop()->rounds().size() == 4; },
                             std::chrono::seconds(5)));
  const auto& followed = *p.panel.design_view().loop();
  ASSERT_TRUE(followed.rounds()[2].measured.has_value());
  EXPECT_EQ(followed.rounds()[2].measured->position, Eigen::Vector2d(0.25 + 0.01, -1.19 - 0.02));
  ASSERT_NE(followed.next_print(), nullptr);
  EXPECT_EQ(followed.next_print()->number, 4);

  p.panel.open_design_loop(dir / "not_a_loop");
  EXPECT_THAT(p.panel.error(), HasSubstr("loop.json"));
  ASSERT_TRUE(p.panel.design_view().loop().has_value());
  EXPECT_EQ(p.panel.design_view().loop()->folder(), loop);
}

}  // namespace
}  // namespace nibrig::ui::panel
