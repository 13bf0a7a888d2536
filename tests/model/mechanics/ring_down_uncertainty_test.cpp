// The ring-down fit's uncertainty against a hidden truth: a printed bar of a material the fit does
// not know (its modulus and damping), its release simulated on the bar's FEM modes with sensor
// noise, fitted from the table's PLA values. The truth must lie within the uncertainty the fit
// reports, as often as a standard deviation promises, and a fitted material saved in the lab's
// table must then be the one the library's prediction (the bar's FEM modes) uses by name.
#include "model/mechanics/ring_down_uncertainty.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <random>

#include "model/io/bundled_assets.hpp"
#include "model/mechanics/design_model.hpp"
#include "model/mechanics/lab_materials.hpp"
#include "model/mechanics/mode_report.hpp"
#include "model/mechanics/ring_down_calibration.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::mechanics {
namespace {

// The paper's bar in the table's PLA: the reference the fit starts from, solved once.
const DesignModel& pla_bar() {
  static const DesignModel model = [] {
    const MaterialTable table = read_material_file(io::default_materials());
    return build_design_model(bar_design(BarGeometry{}, "PLA"), table);
  }();
  return model;
}

// The hidden truth: 0.71 × PLA's datasheet modulus (off the fit's 5 % grid) and a first-mode
// damping ratio near 1 %, a printed polymer's; a release between samples, an unknown gain.
struct HiddenBar {
  double modulus_ratio = 0.71;
  double lambda = 2.9e-4;   // s
  double release = 0.1234;  // s
  double gain = 0.8;
  double rate = 2000.0;        // Hz: the first mode near 11 Hz and the next ones well below Nyquist
  std::size_t samples = 3000;  // 1.5 s: the first mode decays to e^{-ζωt} ≈ 0.5 %
};

io::AccelerationTrace hidden_trace(const HiddenBar& h, double noise, unsigned seed) {
  const modal::ModalModel truth =
      rescale_modulus(pla_bar().modal, h.modulus_ratio, {0.0, h.lambda});
  io::AccelerationTrace trace{h.rate, simulate_release(truth, 0.05, h.rate, h.samples, h.release)};
  for (double& a : trace.acceleration_m_s2) a *= h.gain;
  add_relative_noise(trace.acceleration_m_s2, noise, seed);
  return trace;
}

RingDownOptions pla_options() {
  RingDownOptions o;
  o.reference_modulus = body_material(pla_bar()).youngs_modulus;
  return o;
}

TEST(RingDownUncertainty, TheHiddenTruthLiesWithinTheReportedUncertainty) {
  const HiddenBar h;
  const double true_modulus = h.modulus_ratio * pla_options().reference_modulus;
  int seeds = 0, outside_two_sd = 0;
  double z_squares = 0.0, worst_z = 0.0;
  for (unsigned seed = 1; seed <= 20; ++seed, ++seeds) {
    // 5 % noise: a cheap accelerometer through an audio input, as in ring_down_test.
    const auto trace = hidden_trace(h, 0.05, seed);
    const RingDownFit fit = fit_ring_down(pla_bar().modal, pla_options(), trace);
    const RingDownUncertainty u = ring_down_uncertainty(pla_bar().modal, pla_options(), trace, fit);
    const double z_e = (fit.youngs_modulus - true_modulus) / u.youngs_modulus_sd;
    const double z_l = (fit.rayleigh_stiffness - h.lambda) / u.rayleigh_stiffness_sd;
    for (double z : {z_e, z_l}) {
      z_squares += z * z;
      worst_z = std::max(worst_z, std::abs(z));
      if (std::abs(z) > 2) ++outside_two_sd;
    }
    // White noise leaves uncorrelated residuals: nothing to widen (|ρ| of 3000 white samples is
    // about 1/√3000 ≈ 0.02; 0.1 is five of those).
    EXPECT_LT(std::abs(u.residual_correlation), 0.1) << "seed " << seed;
    // The bounds are informative: a 5 % noise on 3000 samples pins E to well under 1 %.
    EXPECT_LT(u.youngs_modulus_sd, 0.01 * true_modulus) << "seed " << seed;
  }
  // 40 z-scores (E and λ of 20 seeds). With honest standard deviations each falls outside ±2 with
  // probability 4.6 %: 1.8 expected, and 7 or more has binomial probability 0.3 %. Fixed seeds make
  // the count reproducible; the bound says how far from nominal coverage it may be.
  EXPECT_LE(outside_two_sd, 6) << "worst |z| " << worst_z;
  // And they are not inflated either: the z-scores' RMS is 1 for honest ones; with E's and λ's z of
  // a trace correlated, about 20 independent pairs give it a spread near 0.16, and [0.6, 1.5] lies
  // beyond 2.5 of those each side.
  const double z_rms = std::sqrt(z_squares / (2.0 * seeds));
  EXPECT_GT(z_rms, 0.6);
  EXPECT_LT(z_rms, 1.5);
  std::printf(
      "hidden truth over %d seeds: %d of %d z-scores outside 2 sd, RMS z %.2f, worst %.2f\n", seeds,
      outside_two_sd, 2 * seeds, z_rms, worst_z);
}

TEST(RingDownUncertainty, CorrelatedResidualsWidenTheBounds) {
  // Noise smoothed over 8 samples (a hum, or a model that misses a mode) is as large but far less
  // informative than white noise: the bounds must grow, by about √((1+ρ)/(1−ρ)).
  const HiddenBar h;
  const io::AccelerationTrace clean = hidden_trace(h, 0.0, 1);
  double rms = 0.0;
  for (double a : clean.acceleration_m_s2) rms += a * a;
  rms = std::sqrt(rms / static_cast<double>(clean.acceleration_m_s2.size()));
  std::mt19937 generator(7);
  std::normal_distribution<double> unit(0.0, 1.0);
  std::vector<double> noise(clean.acceleration_m_s2.size());
  for (double& n : noise) n = 0.05 * rms * unit(generator);
  io::AccelerationTrace white = clean, coloured = clean;
  for (std::size_t i = 0; i < noise.size(); ++i) {
    white.acceleration_m_s2[i] += noise[i];
    double sum = 0.0;
    for (std::size_t k = 0; k < 8 && k <= i; ++k) sum += noise[i - k];
    coloured.acceleration_m_s2[i] += sum / std::sqrt(8.0);  // the same RMS as the white noise
  }
  const auto fw = fit_ring_down(pla_bar().modal, pla_options(), white);
  const auto fc = fit_ring_down(pla_bar().modal, pla_options(), coloured);
  const auto uw = ring_down_uncertainty(pla_bar().modal, pla_options(), white, fw);
  const auto uc = ring_down_uncertainty(pla_bar().modal, pla_options(), coloured, fc);
  // A moving sum over 8 samples has lag-one correlation 7/8.
  EXPECT_NEAR(uc.residual_correlation, 7.0 / 8.0, 0.05);
  EXPECT_NEAR(uc.variance_inflation, (1 + uc.residual_correlation) / (1 - uc.residual_correlation),
              1e-9);
  // Inflation (1 + 7/8)/(1 − 7/8) = 15: the standard deviation about √15 ≈ 3.9 times white noise's,
  // give or take how the smoothed noise sits against the modes (a factor 2 either way).
  EXPECT_GT(uc.youngs_modulus_sd, 2.0 * uw.youngs_modulus_sd);
}

TEST(RingDownUncertainty, AFittedMaterialSavedByNameIsTheOnePredictionsUse) {
  const auto store = nibrig::test::scratch_dir("ring_down_lab_store");
  const nibrig::test::ScopedEnvironment lab("NIBRIG_MATERIALS", store.string());
  const HiddenBar h;
  RingDownCalibrationOptions options;
  options.name = "lab-pla-hidden";
  options.provenance = {{"recording", "simulated"}, {"printer", "prusa-mk3s"}};
  const RingDownCalibration calibration =
      calibrate_ring_down(pla_bar(), hidden_trace(h, 0.05, 3), options);
  const MaterialTable bundled = read_material_file(io::default_materials());
  const auto file =
      save_lab_material(calibration.material, calibration.calibration, bundled, false);
  EXPECT_EQ(file.parent_path(), store);

  // Found by name through the table every command reads, after the bundled ones.
  const MaterialTable table = read_material_table(io::default_materials());
  const Material& found = table.find("LAB-PLA-HIDDEN");  // names are case-insensitive
  EXPECT_EQ(found.basis, "fitted");
  EXPECT_EQ(found.youngs_modulus, calibration.fit.youngs_modulus);  // the saved number, exactly
  EXPECT_EQ(table.materials().back().name, "lab-pla-hidden");

  // The bar's FEM in the saved material rings where the fit said: K scales with E on the same
  // mesh, so the first mode agrees to the eigensolver's precision (1e-6 relative is generous).
  const DesignModel refit = build_design_model(bar_design(BarGeometry{}, "lab-pla-hidden"), table);
  EXPECT_NEAR(refit.modal.omega.front() / (2 * M_PI), calibration.fit.first_mode_hz,
              1e-6 * calibration.fit.first_mode_hz);
  // And its damping is the fitted one: ζ₁ = λω₁/2.
  EXPECT_NEAR(refit.modal.zeta.front(), calibration.fit.first_mode_damping_ratio,
              1e-6 * calibration.fit.first_mode_damping_ratio);
}

}  // namespace
}  // namespace nibrig::model::mechanics
