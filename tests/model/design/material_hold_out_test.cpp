// The material axis of the Sec. 5.3 check on synthetic data whose DM95 curve lies exactly on the
// line between VeroClear and DM85 at a known fraction: held out, DM95 is predicted exactly and
// beats both baselines, and the fraction the fitted curves put it at is the one it was built with.
// The equal-modulus fraction is checked against the mechanics' own mix of the bundled materials.
#include "model/design/material_hold_out.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "model/design/mixed_design.hpp"
#include "model/forcing/curve_jackknife.hpp"
#include "model/forcing/hermite_curve.hpp"
#include "tests/model/forcing/synthetic_exemplars.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::design {
namespace {

constexpr double kTrueFraction = 0.3;

// The synthetic truth with ln m(DM95) replaced by kTrueFraction × ln m(DM85) (ln m(vero) ≡ 0).
forcing::test::SyntheticTruth mixable_truth() {
  auto truth = forcing::test::make_synthetic_truth();
  std::vector<double> new_dm95;
  for (double k : truth.material.at("DM85")) new_dm95.push_back(kTrueFraction * k);
  for (auto& e : truth.exemplars) {
    if (e.material != "DM95") continue;
    for (auto& row : e.measured.amplitude_m_s2)
      for (std::size_t j = 0; j < row.size(); ++j) {
        const double f = e.measured.frequencies_hz[j];
        row[j] *= std::exp(forcing::hermite_value(truth.knots, new_dm95, f) -
                           forcing::hermite_value(truth.knots, truth.material.at("DM95"), f));
      }
  }
  truth.material["DM95"] = new_dm95;
  return truth;
}

TEST(MaterialHoldOut, AnExactMixIsPredictedExactlyAndBeatsBothBaselines) {
  const auto truth = mixable_truth();
  const MaterialHoldOut held = hold_out_material(truth.exemplars, "DM95", "vero", "DM85", 0.3);
  EXPECT_EQ(held.model.material_log_gain.count("DM95"), 0u);
  ASSERT_EQ(held.predictions.size(), 6u);  // DM95 on a (three tips), b (one) and c (two)
  for (const auto& r : held.predictions) {
    ASSERT_TRUE(r.not_predictable.empty()) << r.tool << " on " << r.surface;
    EXPECT_LT(r.comparison.interpolated.rms_db, 1e-6) << r.tool << " on " << r.surface;
    ASSERT_EQ(r.comparison.baselines.size(), 2u);  // vero alone, DM85 alone
    EXPECT_TRUE(r.comparison.beats_every_baseline()) << r.tool << " on " << r.surface;
  }
  EXPECT_EQ(summarize(held.predictions).beats_every_baseline, 6);
  // The measured neighbours: the same tip in vero and in DM85 on the same surface, when measured.
  const auto on_a = std::find_if(held.predictions.begin(), held.predictions.end(),
                                 [](const auto& r) { return r.surface == "a"; });
  EXPECT_GT(on_a->measured_neighbour_rms_db[0], 0.0);
  EXPECT_GT(on_a->measured_neighbour_rms_db[1], 0.0);
}

TEST(MaterialHoldOut, TheResolutionFindsTheFractionTheCurveWasBuiltAt) {
  const auto truth = mixable_truth();
  const auto jackknife = forcing::jackknife_curves(truth.exemplars);
  // Predicted at a wrong fraction: the deviation is (0.3 − 0.9)·ln m(DM85), knot by knot.
  const MaterialResolution r = material_resolution(jackknife, "DM95", "vero", "DM85", 0.9);
  ASSERT_EQ(r.deviation.size(), truth.knots.size());
  for (std::size_t k = 0; k < truth.knots.size(); ++k) {
    EXPECT_NEAR(r.effect[k], truth.material.at("DM85")[k], 1e-9) << k;
    EXPECT_NEAR(r.deviation[k], (kTrueFraction - 0.9) * truth.material.at("DM85")[k], 1e-9) << k;
    EXPECT_NEAR(r.deviation_se[k], 0.0, 1e-9) << k;  // no noise: every replicate agrees
  }
  EXPECT_NEAR(r.fitted_fraction, kTrueFraction, 1e-9);
  EXPECT_NEAR(r.fitted_fraction_se, 0.0, 1e-9);

  auto noisy = mixable_truth();
  forcing::test::add_log_noise(noisy.exemplars, 0.2, 3);
  const MaterialResolution n = material_resolution(forcing::jackknife_curves(noisy.exemplars),
                                                   "DM95", "vero", "DM85", kTrueFraction);
  EXPECT_GT(n.fitted_fraction_se, 0.0);
  EXPECT_LT(std::abs(n.fitted_fraction - kTrueFraction), 3 * n.fitted_fraction_se);
}

TEST(MaterialHoldOut, TheEqualModulusFractionIsTheMechanicsOwnMix) {
  const auto assets = nibrig::test::assets_dir();
  const auto materials = mechanics::read_material_table(assets / "materials.json");
  const double f = equal_modulus_fraction(materials, "DM95", "vero", "DM85");
  EXPECT_GT(f, 0.0);
  EXPECT_LT(f, 1.0);
  // The mix mixed_design builds at that fraction has DM95's Young's modulus.
  const auto template_design =
      mechanics::read_design(assets / "designs" / "stylus_vero_tip2mm.json", materials);
  const DesignPoint point{{{"vero", 1 - f}, {"DM85", f}}, 0.002};
  const MixedDesign mixed = mixed_design(point, template_design, materials);
  EXPECT_NEAR(mixed.materials.find("mix " + to_string(point)).youngs_modulus,
              materials.find("DM95").youngs_modulus, 1e-6 * materials.find("DM95").youngs_modulus);
  // DM85 is softer than both VeroClear and DM95: no mix of them has its modulus.
  EXPECT_THROW(equal_modulus_fraction(materials, "DM85", "vero", "DM95"), std::invalid_argument);
}

TEST(MaterialHoldOut, RefusesWhatCannotBeHeldOut) {
  const auto truth = forcing::test::make_synthetic_truth();
  EXPECT_THROW(hold_out_material(truth.exemplars, "DM85", "vero", "DM85", 0.5),
               std::invalid_argument);  // one of its own mix
  EXPECT_THROW(hold_out_material(truth.exemplars, "DM95", "vero", "DM85", 1.5),
               std::invalid_argument);
  try {
    hold_out_material(truth.exemplars, "teflon", "vero", "DM85", 0.5);
    FAIL() << "no exemplar is of teflon";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("no exemplar is of teflon"), std::string::npos)
        << e.what();
  }
  // Without its reference material the rest cannot be fitted, and says so.
  EXPECT_THROW(hold_out_material(truth.exemplars, "vero", "DM95", "DM85", 0.5),
               std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::model::design
