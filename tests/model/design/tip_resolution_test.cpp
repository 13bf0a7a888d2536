// What the data can resolve of the tip interpolation, on synthetic data whose 2 mm curve lies
// exactly on the line between the 1 and 4 mm curves: the effect and the deviation must come out as
// built, with no spread when there is no noise and a spread that covers the truth when there is.
#include <gtest/gtest.h>

#include <cmath>

#include "model/design/interpolation_check.hpp"
#include "model/forcing/curve_jackknife.hpp"
#include "model/forcing/hermite_curve.hpp"
#include "tests/model/forcing/synthetic_exemplars.hpp"

namespace nibrig::model::design {
namespace {

// The synthetic truth with its 4 mm curve replaced by −2 × the 1 mm curve, so that the 2 mm curve
// (the reference, 0) is exactly the interpolation a third of the way from 1 to 4 mm.
forcing::test::SyntheticTruth interpolable_truth() {
  auto truth = forcing::test::make_synthetic_truth();
  std::vector<double> new_four;
  for (double k : truth.tip.at(0.001)) new_four.push_back(-2 * k);
  for (auto& e : truth.exemplars) {
    if (!forcing::same_tip(e.tip_diameter_m, 0.004)) continue;
    for (auto& row : e.measured.amplitude_m_s2)
      for (std::size_t j = 0; j < row.size(); ++j) {
        const double f = e.measured.frequencies_hz[j];
        row[j] *= std::exp(forcing::hermite_value(truth.knots, new_four, f) -
                           forcing::hermite_value(truth.knots, truth.tip.at(0.004), f));
      }
  }
  truth.tip[0.004] = new_four;
  return truth;
}

TEST(TipResolution, RecoversAnExactlyInterpolableTipWithoutSpread) {
  const auto truth = interpolable_truth();
  const TipResolution r = tip_resolution(forcing::jackknife_curves(truth.exemplars), 0.002);
  EXPECT_DOUBLE_EQ(r.lower_tip_m, 0.001);
  EXPECT_DOUBLE_EQ(r.upper_tip_m, 0.004);
  EXPECT_EQ(r.tools, 9u);
  ASSERT_EQ(r.effect.size(), truth.knots.size());
  for (std::size_t k = 0; k < truth.knots.size(); ++k) {
    EXPECT_NEAR(r.effect[k], -3 * truth.tip.at(0.001)[k], 1e-9) << k;
    EXPECT_NEAR(r.deviation[k], 0.0, 1e-9) << k;
    EXPECT_NEAR(r.effect_se[k], 0.0, 1e-9) << k;
    EXPECT_NEAR(r.deviation_se[k], 0.0, 1e-9) << k;
  }
}

TEST(TipResolution, WithNoiseTheErrorsCoverTheTruth) {
  auto truth = interpolable_truth();
  forcing::test::add_log_noise(truth.exemplars, 0.2, 11);
  const TipResolution r = tip_resolution(forcing::jackknife_curves(truth.exemplars), 0.002);
  // The truth within 3 standard errors at (nearly) every knot: 11 knots, two statistics.
  int covered = 0;
  for (std::size_t k = 0; k < truth.knots.size(); ++k) {
    EXPECT_GT(r.effect_se[k], 0.0);
    EXPECT_GT(r.deviation_se[k], 0.0);
    covered += std::abs(r.effect[k] + 3 * truth.tip.at(0.001)[k]) < 3 * r.effect_se[k];
    covered += std::abs(r.deviation[k]) < 3 * r.deviation_se[k];
  }
  EXPECT_GE(covered, 20);
}

TEST(TipResolution, RefusesATipWithoutNeighboursOnBothSides) {
  const auto truth = forcing::test::make_synthetic_truth();
  EXPECT_THROW(tip_resolution(forcing::jackknife_curves(truth.exemplars), 0.004),
               std::invalid_argument);
  EXPECT_THROW(tip_resolution(forcing::jackknife_curves(truth.exemplars), 0.003),
               std::invalid_argument);
  // The hold-out itself says why, as `nibrig forcing holdout --tip 4` prints it.
  try {
    hold_out_tip(truth.exemplars, 0.004);
    FAIL() << "the 4 mm tip has no larger neighbour";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "holding out the 4 mm tips: the other tips do not lie on both sides of it");
  }
  EXPECT_THROW(hold_out_tip(truth.exemplars, 0.003), std::invalid_argument);  // no such tool
}

}  // namespace
}  // namespace nibrig::model::design
