// The substitutes of a mix, with a stand-in for the prediction whose placements are known: the
// distances are those between the placements' means, and the nearest to the mix comes first.
#include "model/design/single_material_substitute.hpp"

#include <gtest/gtest.h>

#include <map>

namespace nibrig::model::design {
namespace {

space::Placement at(double x, double y) {
  space::Placement p;
  p.mean = Eigen::Vector2d(x, y);
  p.covariance = Eigen::Matrix2d::Zero();  // certain: the distances' sds are 0
  return p;
}

TEST(SingleMaterialSubstitute, EachMaterialAloneAtTheMixsTipNearestFirst) {
  const auto mix = parse_design_point("DM85:0.62,vero:0.38,tip=2.7mm");
  const space::Placement mix_place = at(0, 0), target = at(3, 4);
  // Each material alone lands here; the mix's distances are to (0, 0).
  const std::map<std::string, space::Placement> alone{{"DM85", at(0, 1)}, {"vero", at(2, 0)}};
  std::vector<DesignPoint> asked;
  const Evaluate from_mix = [&](const DesignPoint& p) {
    asked.push_back(p);
    Candidate c;
    c.point = p;
    c.placement = alone.at(p.mix.front().material);
    c.distance = (c.placement.mean - mix_place.mean).norm();
    return c;
  };
  const auto subs = single_material_substitutes(mix, from_mix, target);
  ASSERT_EQ(subs.size(), 2u);
  ASSERT_EQ(asked.size(), 2u);  // one prediction each
  for (const auto& p : asked) {
    EXPECT_EQ(p.mix.size(), 1u);
    EXPECT_DOUBLE_EQ(p.tip_diameter_m, mix.tip_diameter_m);
  }
  EXPECT_EQ(subs[0].point.mix.front().material, "DM85");
  EXPECT_DOUBLE_EQ(subs[0].cost, 1.0);
  EXPECT_NEAR(*subs[0].to_target, std::hypot(3.0, 3.0), 1e-12);  // (0, 1) to (3, 4)
  // Certain placements: every draw is the same distance, and the sd is what rounding leaves of a
  // mean square less a squared mean over 2000 draws: well under 1e-5 of the distance.
  EXPECT_NEAR(subs[0].to_target_sd, 0.0, 1e-5 * *subs[0].to_target);
  EXPECT_EQ(subs[1].point.mix.front().material, "vero");
  EXPECT_DOUBLE_EQ(subs[1].cost, 2.0);
  EXPECT_NEAR(*subs[1].to_target, std::hypot(1.0, 4.0), 1e-12);

  // A group of two: the largest of each substitute's two distances. No targets (a design exported
  // for itself): the same costs, no distance to a target.
  const auto group = single_material_substitutes(mix, from_mix, {target, at(0, 5)}, space::GroupAim::largest);
  EXPECT_NEAR(*group[0].to_target, std::max(std::hypot(3.0, 3.0), 4.0), 1e-12);
  EXPECT_NEAR(*group[1].to_target, std::max(std::hypot(1.0, 4.0), std::hypot(2.0, 5.0)), 1e-12);
  const auto alone_ = single_material_substitutes(mix, from_mix, {}, space::GroupAim::largest);
  ASSERT_EQ(alone_.size(), 2u);
  EXPECT_DOUBLE_EQ(alone_[1].cost, 2.0);
  EXPECT_FALSE(alone_[0].to_target.has_value());
}

TEST(SingleMaterialSubstitute, ASingleMaterialNeedsNone) {
  const Evaluate never = [](const DesignPoint&) -> Candidate { throw std::logic_error("predicted"); };
  EXPECT_TRUE(single_material_substitutes(parse_design_point("vero,tip=2mm"), never, at(0, 0)).empty());
}

}  // namespace
}  // namespace nibrig::model::design
