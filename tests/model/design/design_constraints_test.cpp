// Constraints on a printed design: the segment of a line they allow against the interval worked
// out by hand, the searches keeping to it (checked against brute-force scans of the allowed part),
// and refusals that name what leaves nothing.
#include "model/design/design_constraints.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "model/design/design_search.hpp"
#include "tests/model/design/search_objective.hpp"

namespace nibrig::model::design {
namespace {

using ::testing::HasSubstr;

const DesignPoint kVero1mm = parse_design_point("vero,tip=1mm");
const DesignPoint kDm85At4mm = parse_design_point("DM85,tip=4mm");

using search_testing::objective;

// Along vero 1 mm → DM85 4 mm, λ is the DM85 fraction and the tip is 1 + 3λ mm.
TEST(DesignConstraints, EachConstraintCutsTheLineWhereItsLinearFormSays) {
  DesignConstraints tips;
  tips.min_tip_m = 0.0015, tips.max_tip_m = 0.003;
  const auto [lo, hi] = feasible_segment(kVero1mm, kDm85At4mm, tips);
  EXPECT_NEAR(lo, 1.0 / 6, 1e-12);  // 1 + 3λ = 1.5
  EXPECT_NEAR(hi, 2.0 / 3, 1e-12);  // 1 + 3λ = 3

  DesignConstraints no_vero;
  no_vero.materials = {"DM85"};
  const auto only_dm85 = feasible_segment(kVero1mm, kDm85At4mm, no_vero);
  EXPECT_NEAR(only_dm85.first, 1.0, 1e-9);
  EXPECT_NEAR(only_dm85.second, 1.0, 1e-12);

  DesignConstraints cost;
  cost.cost = {{"vero", 1.0}, {"DM85", 3.0}};
  cost.max_cost = 2.0;  // 1 + 2λ ≤ 2
  EXPECT_NEAR(feasible_segment(kVero1mm, kDm85At4mm, cost).second, 0.5, 1e-9);
  EXPECT_DOUBLE_EQ(design_cost(interpolate(kVero1mm, kDm85At4mm, 0.25), cost.cost), 1.5);

  auto both = tips;
  both.cost = cost.cost, both.max_cost = cost.max_cost;
  const auto together = feasible_segment(kVero1mm, kDm85At4mm, both);
  EXPECT_NEAR(together.first, 1.0 / 6, 1e-12);
  EXPECT_NEAR(together.second, 0.5, 1e-9);
}

TEST(DesignConstraints, WhatLeavesNothingIsNamed) {
  DesignConstraints wide;
  wide.min_tip_m = 0.005;
  EXPECT_THAT([&] { feasible_segment(kVero1mm, kDm85At4mm, wide); },
              ::testing::ThrowsMessage<std::invalid_argument>(HasSubstr("at least 5 mm")));
  DesignConstraints dm85_only;
  dm85_only.materials = {"DM85"};
  EXPECT_THAT([&] { feasible_segment(kVero1mm, parse_design_point("vero,tip=4mm"), dm85_only); },
              ::testing::ThrowsMessage<std::invalid_argument>(HasSubstr("no vero (not allowed)")));
  // λ ≤ 1/6 by the tip, λ ≥ 0.75 by the cost 3 − 2λ ≤ 1.5: each allows part, together nothing.
  DesignConstraints apart;
  apart.max_tip_m = 0.0015;
  apart.cost = {{"vero", 3.0}, {"DM85", 1.0}};
  apart.max_cost = 1.5;
  EXPECT_THAT([&] { feasible_segment(kVero1mm, kDm85At4mm, apart); },
              ::testing::ThrowsMessage<std::invalid_argument>(HasSubstr("together")));
  DesignConstraints priced;
  priced.cost = {{"vero", 1.0}};
  priced.max_cost = 2.0;
  EXPECT_THAT([&] { feasible_segment(kVero1mm, kDm85At4mm, priced); },
              ::testing::ThrowsMessage<std::invalid_argument>(HasSubstr("DM85")));
  EXPECT_THAT(broken_constraint(kDm85At4mm, apart), HasSubstr("above the largest allowed"));
  EXPECT_EQ(broken_constraint(parse_design_point("DM85,tip=1.5mm"), apart), "");
}

TEST(DesignConstraints, TheLineSearchFindsTheBestAllowedDesign) {
  // The minimum at λ = 0.62 lies beyond the cost limit (λ ≤ 0.5): the best allowed is at the limit.
  const auto f = [](double fraction, double) { return 0.2 + 3 * std::pow(fraction - 0.62, 2); };
  LineSearchOptions options;
  options.constraints.cost = {{"vero", 1.0}, {"DM85", 3.0}};
  options.constraints.max_cost = 2.0;
  const auto result = line_search(kVero1mm, kDm85At4mm, objective(f), options);
  for (const auto& c : result.evaluated) EXPECT_EQ(broken_constraint(c.point, options.constraints), "") << label(c.point);
  // The refinement's tolerance is 1 % of the searched segment (half the line).
  EXPECT_NEAR(result.best().point.fraction_of("DM85"), 0.5, 0.005);
  // One design allowed: that design, evaluated once.
  options.constraints = {};
  options.constraints.materials = {"DM85"};
  const auto one = line_search(kVero1mm, kDm85At4mm, objective(f), options);
  ASSERT_EQ(one.evaluated.size(), 1u);
  EXPECT_EQ(label(one.best().point), label(kDm85At4mm));
}

TEST(DesignConstraints, TheRangeSearchKeepsToTheAllowedTipsAndMaterials) {
  const auto f = [](double fraction, double tip_mm) {
    return std::pow(fraction - 0.62, 2) + std::pow(tip_mm - 2.7, 2);
  };
  RangeSearchOptions options;
  options.constraints.max_tip_m = 0.002;
  const auto result = range_search(objective(f), options);
  for (const auto& c : result.evaluated) EXPECT_EQ(broken_constraint(c.point, options.constraints), "") << label(c.point);
  // Brute force over the allowed rectangle: the minimum is at the tip limit, fraction 0.62.
  EXPECT_NEAR(result.best().point.tip_diameter_m, 0.002, 1e-12);
  // The grid's last refinement steps the fraction by 1/16: the best lies within half a step.
  EXPECT_NEAR(result.best().point.fraction_of("DM85"), 0.62, 1.0 / 32);

  options.constraints = {};
  options.constraints.materials = {"DM85"};
  const auto dm85 = range_search(objective(f), options);
  for (const auto& c : dm85.evaluated) EXPECT_DOUBLE_EQ(c.point.fraction_of("DM85"), 1.0);
  // The first grid steps the tip by 1 mm, the last refinement by a quarter of that: half of it.
  EXPECT_NEAR(dm85.best().point.tip_diameter_m, 0.0027, 0.001 / 4 / 2 + 1e-12);

  options.constraints = {};
  options.constraints.min_tip_m = 0.005;
  EXPECT_THAT([&] { range_search(objective(f), options); },
              ::testing::ThrowsMessage<std::invalid_argument>(HasSubstr("outside the fitted tips")));
}

// Issue 46: a NaN or negative cost was taken and a search ran 14 s for nothing; the check names the
// option a face gave it as.
TEST(DesignConstraintChecks, RefuseNonFiniteAndNegativeCostsNamingThem) {
  DesignConstraints c;
  c.cost = {{"vero", 1.0}};
  c.max_cost = std::nan("");
  try {
    check_constraints(c, {"--min-tip-mm", "--max-tip-mm", "--cost", "--max-cost"});
    FAIL() << "a NaN limit passed";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), HasSubstr("--max-cost: nan"));
  }
  c.max_cost = 2.0;
  c.cost["vero"] = -1.0;
  try {
    check_constraints(c);
    FAIL() << "a negative cost passed";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), HasSubstr("cost of vero: -1"));
  }
}

// "--allow steel" on a line of vero and DM85 left nothing, and the message did not say why.
TEST(DesignConstraintChecks, NameAnAllowedMaterialTheLineDoesNotHold) {
  DesignConstraints c;
  c.materials = {"steel"};
  try {
    feasible_segment(kVero1mm, kDm85At4mm, c);
    FAIL() << "a line of no allowed material had a segment";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), HasSubstr("allowed steel: not a material of the line"));
  }
}

}  // namespace
}  // namespace nibrig::model::design
