// A material the lab's model does not know, calibrated from its 1 mm and 4 mm prints on the six
// surfaces: without noise its curve is recovered exactly; with the rig's noise (the catalog's own
// repeatability) the hidden curve lies within the uncertainty the calibration reports, as often as
// that uncertainty says, over many draws; and prints that cannot be calibrated from are refused.
#include "model/forcing/material_calibration.hpp"

#include <gtest/gtest.h>

#include <boost/math/distributions/students_t.hpp>
#include <cmath>

#include "model/forcing/leave_one_out.hpp"
#include "tests/model/forcing/calibration_truth.hpp"

namespace nibrig::model::forcing {
namespace {

// The 1 mm and 4 mm prints of a material with curve `knots`, on every surface of the model; each
// print's curve offset from it by a constant drawn with SD `print_offset` (how one print sits, its
// tip curve's error), the same on every surface it is measured on.
std::vector<ForcingExemplar> hidden_material_prints(
    const test::LabTruth& truth, const std::string& material, const std::vector<double>& knots,
    unsigned seed, double print_offset = 0.0, const std::vector<double>& tips = {0.001, 0.004}) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> offset(0.0, 1.0);
  std::vector<ForcingExemplar> prints;
  for (double tip : tips) {
    std::vector<double> print_knots = knots;
    const double shift = print_offset * offset(rng);
    for (double& k : print_knots) k += shift;
    for (const auto& [surface, forcing] : truth.model.surface_forcing)
      prints.push_back(test::simulated_print(truth, material + std::to_string(int(tip * 1e3)),
                                             material, tip, surface, print_knots, forcing, rng));
  }
  return prints;
}

std::vector<double> hidden_material_curve(std::size_t knots, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, 0.5);
  std::vector<double> out;
  for (std::size_t k = 0; k < knots; ++k) out.push_back(normal(rng));
  return out;
}

TEST(MaterialCalibration, NoiselessPrintsGiveTheCurveExactly) {
  test::LabTruth truth = test::make_lab_truth(3);
  truth.noise_log = 0.0;
  const auto hidden = hidden_material_curve(truth.model.knot_frequencies_hz.size(), 4);
  const auto prints = hidden_material_prints(truth, "pla", hidden, 5);
  const MaterialCalibration c = calibrate_material(truth.model, prints, "pla");
  ASSERT_EQ(c.log_gain.size(), hidden.size());
  // Linear least squares on exact data: round-off only.
  for (std::size_t k = 0; k < hidden.size(); ++k) {
    EXPECT_NEAR(c.log_gain[k], hidden[k], 1e-9) << k;
    EXPECT_LT(c.log_gain_se[k], 1e-9) << k;
  }
  EXPECT_EQ(c.exemplars, 12u);
  EXPECT_EQ(c.prints, 2u);
  EXPECT_EQ(c.degrees_of_freedom, 11.0);  // the prints agree exactly: no between part
  EXPECT_EQ(c.print_log_gain_sd, 0.0);
  EXPECT_LT(c.residual_rms_db, 1e-6);
  EXPECT_EQ(c.model.material_curve("pla"), c.log_gain);
  EXPECT_EQ(c.model.material_log_gain_se.at("pla"), c.log_gain_se);
  EXPECT_EQ(truth.model.material_log_gain.count("pla"), 0u);  // the input is left as it was
  // The calibrated model predicts a print it never saw (2 mm on stone) exactly.
  std::mt19937 rng(6);
  const auto unseen = test::simulated_print(truth, "pla2", "pla", 0.002, "stone", hidden,
                                            truth.model.surface_forcing.at("stone"), rng);
  const auto predicted = c.model.predict(unseen.response_magnitude, "stone", 0.002, "pla");
  EXPECT_LT(log_spectrum_error(predicted, unseen.measured).rms_db, 1e-6);
}

// Over 40 draws of a hidden curve and of the rig's noise (11 knots each): how often the truth lies
// within the reported standard errors. With 12 exemplars the error over its SE is a Student t with
// 11 degrees of freedom (the cluster-robust SE's small-sample behaviour), which puts 93 % within
// ±2 SE, 95 % within the t-interval and 66 % within ±1 SE. The bounds allow for 440 knots that are
// correlated within a draw (binomial SE ≈ 1.2 %, a few times that with the correlation): coverage
// well under the nominal means the SE is too small (the bins counted as independent would give
// ~1 %), and too much within ±1 SE means it is inflated (an SE that can not fail).
TEST(MaterialCalibration, TheHiddenCurveLiesWithinTheReportedUncertainty) {
  std::size_t within_two = 0, within_t = 0, within_one = 0, knots = 0;
  double residual_db = 0.0, repeatability = 0.0, se_db = 0.0;
  const int draws = 40;
  for (int draw = 0; draw < draws; ++draw) {
    const test::LabTruth truth = test::make_lab_truth(100 + draw);
    repeatability = truth.repeatability_db;
    const auto hidden = hidden_material_curve(truth.model.knot_frequencies_hz.size(), 200 + draw);
    const auto prints = hidden_material_prints(truth, "resin", hidden, 300 + draw);
    const MaterialCalibration c = calibrate_material(truth.model, prints, "resin");
    const boost::math::students_t t(c.degrees_of_freedom);
    const double t95 = boost::math::quantile(boost::math::complement(t, 0.025));
    for (std::size_t k = 0; k < hidden.size(); ++k) {
      const double z = std::abs(c.log_gain[k] - hidden[k]) / c.log_gain_se[k];
      within_two += z <= 2.0;
      within_t += z <= t95;
      within_one += z <= 1.0;
      se_db += log_gain_to_db(c.log_gain_se[k]);
      ++knots;
    }
    residual_db += c.residual_rms_db;
  }
  const auto fraction = [&](std::size_t n) { return double(n) / double(knots); };
  std::cout << "hidden-truth coverage over " << draws << " draws, " << knots
            << " knots: within 2 SE " << fraction(within_two) << ", within the 95 % t-interval "
            << fraction(within_t) << ", within 1 SE " << fraction(within_one) << "; mean SE "
            << se_db / double(knots) << " dB\n";
  EXPECT_GE(fraction(within_two), 0.88);
  EXPECT_GE(fraction(within_t), 0.90);
  EXPECT_LE(fraction(within_one), 0.80);
  // The fit leaves the noise it was given: one recording's, the repeatability over √2 (11 knots
  // absorb a negligible share of 12 × 1482 cells).
  EXPECT_NEAR(residual_db / draws, repeatability / std::sqrt(2.0), 0.05 * repeatability);
}

struct PrintEffectCoverage {
  double within_t = 0.0, within_only_two = 0.0, dof = 0.0;
};

// Over `draws` hidden curves with prints at `tips` whose curves are each shifted by a constant of
// SD 0.1 (0.9 dB): how often the truth lies within the reported t-interval, and within 2 of the
// exemplars' SE alone.
PrintEffectCoverage print_effect_coverage(const std::vector<double>& tips, int draws) {
  std::size_t within_t = 0, within_only_two = 0, knots = 0;
  double dof = 0.0;
  for (int draw = 0; draw < draws; ++draw) {
    const test::LabTruth truth = test::make_lab_truth(700 + draw);
    const auto hidden = hidden_material_curve(truth.model.knot_frequencies_hz.size(), 800 + draw);
    const auto prints = hidden_material_prints(truth, "tpu", hidden, 900 + draw, 0.1, tips);
    const MaterialCalibration c = calibrate_material(truth.model, prints, "tpu");
    const boost::math::students_t t(c.degrees_of_freedom);
    const double t95 = boost::math::quantile(boost::math::complement(t, 0.025));
    for (std::size_t k = 0; k < hidden.size(); ++k) {
      const double error = std::abs(c.log_gain[k] - hidden[k]);
      within_t += error <= t95 * c.log_gain_se[k];
      within_only_two += error <= 2 * c.log_gain_within_se[k];
      ++knots;
    }
    dof += c.degrees_of_freedom;
  }
  return {double(within_t) / double(knots), double(within_only_two) / double(knots), dof / draws};
}

// Prints that differ beyond their exemplars' noise, by a constant of SD 0.1 each (0.9 dB, about
// what the catalog's 1 mm and 4 mm DM95 prints differ by). The exemplars' spread alone then misses
// the truth most of the time; the prints' spread added to it holds it near the 95 % its t-interval
// claims. Each draw is one offset shared by all its knots, so 150 draws give the coverage to about
// ±2 %. With two prints the prints' part has one degree of freedom, and when the two happen to
// agree the interval is narrow though the curve is known no better: Satterthwaite's degrees of
// freedom (~3 here) are then too many, and the coverage falls some 10 % short; a third print
// brings it within a few per cent of nominal. The bounds say so, with the ±2 % and the
// approximation's few per cent.
TEST(MaterialCalibration, PrintsThatDifferWidenTheUncertaintyAsMuchAsTheyDiffer) {
  const PrintEffectCoverage two = print_effect_coverage({0.001, 0.004}, 150);
  const PrintEffectCoverage three = print_effect_coverage({0.001, 0.002, 0.004}, 150);
  std::cout << "prints offset by SD 0.1 (0.9 dB): two prints within the t-interval " << two.within_t
            << " (exemplars alone, 2 SE: " << two.within_only_two << "; " << two.dof
            << " degrees of freedom), three prints " << three.within_t << " ("
            << three.within_only_two << "; " << three.dof << ")\n";
  EXPECT_LT(two.within_only_two, 0.6);
  EXPECT_GE(two.within_t, 0.78);
  EXPECT_GE(three.within_t, 0.88);
  EXPECT_GT(three.within_t, two.within_t);
}

TEST(MaterialCalibration, PrintsThatCannotCalibrateAreRefusedByName) {
  const test::LabTruth truth = test::make_lab_truth(7);
  const auto hidden = hidden_material_curve(truth.model.knot_frequencies_hz.size(), 8);
  auto prints = hidden_material_prints(truth, "petg", hidden, 9);
  const auto refused = [&](const std::vector<ForcingExemplar>& p, const std::string& material,
                           const std::string& expected) {
    try {
      calibrate_material(truth.model, p, material);
      ADD_FAILURE() << "expected a refusal mentioning " << expected;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  };
  refused({prints.front()}, "petg", "at least two");
  refused(prints, "DM85", "already has a curve");
  refused(prints, "tpu", "petg1 on glass is of material 'petg'");
  auto other_surface = prints;
  other_surface[2].surface = "screen";
  refused(other_surface, "petg", "petg1 on screen: the forcing model has no surface 'screen'");
  auto other_tip = prints;
  other_tip[1].tip_diameter_m = 0.003;
  refused(other_tip, "petg", "no 3 mm tip curve");
  auto short_response = prints;
  short_response[0].response_magnitude.pop_back();
  refused(short_response, "petg", "its response has");
}

}  // namespace
}  // namespace nibrig::model::forcing
