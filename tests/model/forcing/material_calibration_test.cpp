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

// The 1 mm and 4 mm prints of a material with curve `knots`, on every surface of the model.
std::vector<ForcingExemplar> hidden_material_prints(const test::LabTruth& truth,
                                                    const std::string& material,
                                                    const std::vector<double>& knots,
                                                    unsigned seed) {
  std::mt19937 rng(seed);
  std::vector<ForcingExemplar> prints;
  for (double tip : {0.001, 0.004})
    for (const auto& [surface, forcing] : truth.model.surface_forcing)
      prints.push_back(test::simulated_print(truth, material + std::to_string(int(tip * 1e3)),
                                             material, tip, surface, knots, forcing, rng));
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
  EXPECT_EQ(c.degrees_of_freedom, 11u);
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
    const boost::math::students_t t(static_cast<double>(c.degrees_of_freedom));
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
