// A calibration's standard errors carried to a predicted tool's descriptors: a surface whose every
// cell is uncertain by s moves log10 of the weighted mean by s·log10(e) and of each band energy (a
// power) by twice that, exactly; one uncertain knot of a material moves them by less, in
// proportion to its share of the mix; none, nothing. Through predict_from_response the covariance
// is added to the tool's own.
#include "model/design/calibration_uncertainty.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "model/design/predicted_tool.hpp"
#include "model/forcing/printed_tool_design.hpp"
#include "model/io/catalog_file.hpp"
#include "model/measure/descriptors.hpp"
#include "model/mechanics/design_model.hpp"
#include "model/modal/frequency_response.hpp"
#include "model/space/catalog_descriptors.hpp"
#include "tests/model/design/hand_made_forcing_model.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::design {
namespace {

const measure::ThresholdCurve& calibration_threshold() {
  static const measure::ThresholdCurve t({10.0, 1000.0}, {0.01, 0.1}, "test threshold");
  return t;
}

DesignPoint half_dm85() { return {{{"DM85", 0.5}, {"vero", 0.5}}, 0.002}; }

std::size_t descriptor_index(const std::vector<std::string>& names, const std::string& name) {
  return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
}

TEST(CalibrationUncertainty, NoErrorsAddNothing) {
  const auto model = hand_made_model();
  const auto spectrum = predict_spectrum(model, half_dm85(), "office", kResponse);
  const auto names = space::all_paper_descriptor_names();
  EXPECT_FALSE(has_calibration_errors(model, half_dm85(), "office"));
  EXPECT_EQ(calibration_descriptor_covariance(model, half_dm85(), "office", spectrum,
                                              calibration_threshold(), names),
            Eigen::MatrixXd::Zero(names.size(), names.size()));
  EXPECT_THROW(calibration_descriptor_covariance(model, half_dm85(), "office", spectrum,
                                                 calibration_threshold(), {"loudness"}),
               std::invalid_argument);
}

TEST(CalibrationUncertainty, AnUncertainSurfaceMovesEveryDescriptorByItsScale) {
  auto model = hand_made_model();
  const double s = 0.1;
  model.surface_log_forcing_se["office"] = {std::vector<double>(5, s), std::vector<double>(5, s)};
  const auto spectrum = predict_spectrum(model, half_dm85(), "office", kResponse);
  const auto names = space::all_paper_descriptor_names();
  ASSERT_TRUE(has_calibration_errors(model, half_dm85(), "office"));
  const Eigen::MatrixXd c = calibration_descriptor_covariance(
      model, half_dm85(), "office", spectrum, calibration_threshold(), names);
  // The weighted mean is linear in the amplitudes, band energies quadratic: scaling every cell by
  // e^s shifts their log10 by s·log10(e) and 2s·log10(e). The central difference is exact for a
  // shift linear in the step, up to round-off.
  const double shift = s / std::numbers::ln10;
  const std::string mean = space::paper_descriptor_names(2).back();
  EXPECT_NEAR(c(descriptor_index(names, mean), descriptor_index(names, mean)), shift * shift, 1e-9);
  const auto bands = space::paper_descriptor_names(4);  // μ and three band energies
  for (std::size_t j = 1; j < bands.size(); ++j) {
    EXPECT_NEAR(c(descriptor_index(names, bands[j]), descriptor_index(names, bands[j])),
                4 * shift * shift, 1e-9)
        << bands[j];
    EXPECT_NEAR(c(descriptor_index(names, bands[j]), descriptor_index(names, mean)),
                2 * shift * shift, 1e-9)
        << bands[j];
  }
  const std::string mu = space::paper_descriptor_names(1).front();
  EXPECT_EQ(c.row(descriptor_index(names, mu)).norm(), 0.0);
}

TEST(CalibrationUncertainty, AnUncertainKnotMovesTheDescriptorsByItsShare) {
  auto model = hand_made_model();
  std::vector<double> se(model.knot_frequencies_hz.size(), 0.0);
  se[4] = 0.2;  // 200 Hz: one of the model's five frequencies sits on it
  model.material_log_gain_se["DM85"] = se;
  const auto names = space::all_paper_descriptor_names();
  const std::string mean = space::paper_descriptor_names(2).back();
  const auto variance = [&](const DesignPoint& p) {
    const auto spectrum = predict_spectrum(model, p, "office", kResponse);
    return calibration_descriptor_covariance(model, p, "office", spectrum, calibration_threshold(),
                                             names)(descriptor_index(names, mean),
                                                    descriptor_index(names, mean));
  };
  const double half = variance(half_dm85());
  const double whole = variance({{{"DM85", 1.0}}, 0.002});
  // One of five frequencies moves, by its share at most (its Hermite weight is 1 on the knot): more
  // than nothing, less than every bin moving together.
  EXPECT_GT(half, 0.0);
  EXPECT_LT(half, std::pow(0.5 * 0.2 / std::numbers::ln10, 2));
  // A mix with half the material: ln m and its error move by half; the variance by a quarter,
  // up to the descriptors' slight curvature between the two spectra.
  EXPECT_NEAR(half / whole, 0.25, 0.05);
  EXPECT_EQ(variance({{{"vero", 1.0}}, 0.002}), 0.0);  // no calibrated material in the mix
}

TEST(CalibrationUncertainty, APredictedToolCarriesItBesideItsOwnError) {
  auto model = hand_made_model();
  model.surface_log_forcing_se["office"] = {std::vector<double>(5, 0.1),
                                            std::vector<double>(5, 0.1)};
  const auto catalog = io::read_catalog(nibrig::test::assets_dir() / "default_catalog.json");
  DescriptorErrorCovariance own;
  own.names = space::all_paper_descriptor_names();
  own.covariance = 1e-4 * Eigen::MatrixXd::Identity(own.names.size(), own.names.size());
  PredictionSetup setup;
  setup.model = &model;
  setup.catalog = &catalog;
  setup.threshold = &calibration_threshold();
  setup.descriptor_errors = &own;
  SimulatedResponse response{"hand made", {{600.0}, {0.01}, {1.0}, {1.0}}, kResponse};
  const PredictedTool tool = predict_from_response(setup, half_dm85(), "office", response);
  const Eigen::MatrixXd added = calibration_descriptor_covariance(
      model, half_dm85(), "office", tool.spectrum, calibration_threshold(), own.names);
  const std::string mean = space::paper_descriptor_names(2).back();
  const std::size_t m = descriptor_index(own.names, mean);
  EXPECT_NEAR(tool.descriptor_errors.covariance(m, m), 1e-4 + added(m, m), 1e-15);
  EXPECT_GT(added(m, m), 0.0);
  // Without a setup error the calibration's alone is carried.
  setup.descriptor_errors = nullptr;
  const PredictedTool alone = predict_from_response(setup, half_dm85(), "office", response);
  ASSERT_FALSE(alone.descriptor_errors.empty());
  EXPECT_NEAR(alone.descriptor_errors.covariance(m, m), added(m, m), 1e-15);
}

}  // namespace
}  // namespace nibrig::model::design

namespace nibrig::model::design {
namespace {

// A lab's PLA fitted to its ring-down, 3 % on E and 10 % on λ, and a 2 mm stylus printed whole of
// it, meshed coarsely (the check is of the propagation, not of the stylus).
struct RingDownCalibratedStylus {
  mechanics::MaterialTable table;
  mechanics::Material lab;
  mechanics::Design design;
  explicit RingDownCalibratedStylus(double modulus_scale = 1.0, double damping_scale = 1.0) {
    const auto bundled =
        mechanics::read_material_file(nibrig::test::assets_dir() / "materials.json");
    lab = bundled.find("PLA");
    lab.name = "lab-pla";
    lab.youngs_modulus *= 0.83 * modulus_scale;
    lab.damping = mechanics::RayleighDamping{0.0, 2.2e-4 * damping_scale};
    lab.youngs_modulus_sd = 0.03 * 0.83 * bundled.find("PLA").youngs_modulus;
    lab.rayleigh_stiffness_sd = 0.1 * 2.2e-4;
    std::vector<mechanics::Material> all = bundled.materials();
    all.push_back(lab);
    table = mechanics::MaterialTable(std::move(all));
    const auto stylus = mechanics::read_design(
        nibrig::test::assets_dir() / "designs" / "stylus_vero_tip2mm.json", table);
    design = forcing::printed_tool_design(forcing::printed_tip_of("lab-pla", table), 0.002, stylus,
                                          table);
    design.mesh_size = 0.005;
    design.modes = 16;
  }
  // The stylus's spectrum when driven flat: |H| on the bundled catalog's grid at two speeds.
  io::VelocitySpectrum spectrum() const {
    const auto model = mechanics::build_design_model(design, table);
    io::VelocitySpectrum s;
    for (double f = 6; f <= 498; f += 2) s.frequencies_hz.push_back(f);
    s.speeds_m_s = {0.017, 0.25};
    std::vector<double> row;
    for (const auto& h : modal::frequency_response(model.modal, s.frequencies_hz))
      row.push_back(0.01 * std::abs(h));
    s.amplitude_m_s2 = {row, row};
    return s;
  }
};

TEST(CalibrationUncertainty, ALabMaterialsRingDownErrorMovesItsStylusAsAFullResolveDoes) {
  const RingDownCalibratedStylus at;
  const auto model = mechanics::build_design_model(at.design, at.table);
  const auto names = space::all_paper_descriptor_names();
  const auto spectrum = at.spectrum();
  const Eigen::MatrixXd covariance = material_constants_covariance(
      model.modal, *at.design.damping, at.lab, spectrum, calibration_threshold(), names);
  // The independent reference: the stylus meshed and solved again at E and λ 1 % either side.
  const std::size_t w = descriptor_index(names, space::paper_descriptor_names(2).back());
  const auto log_mean = [&](const RingDownCalibratedStylus& s) {
    return std::log10(measure::compute_vibration_descriptors(s.spectrum(), calibration_threshold())
                          .weighted_mean);
  };
  const double step = std::log(1.01) - std::log(0.99);
  const double d_modulus =
      (log_mean(RingDownCalibratedStylus(1.01)) - log_mean(RingDownCalibratedStylus(0.99))) / step;
  const double d_damping = (log_mean(RingDownCalibratedStylus(1.0, 1.01)) -
                            log_mean(RingDownCalibratedStylus(1.0, 0.99))) /
                           step;
  const double expected = d_modulus * d_modulus * 0.03 * 0.03 + d_damping * d_damping * 0.1 * 0.1;
  // 1 %: the central differences at ±1 % against the library's ±0.1 % differ by their truncation,
  // O(step²) of the curvature; the modal rescaling itself is exact for a body of one material.
  EXPECT_NEAR(covariance(w, w), expected, 0.01 * expected);
  EXPECT_GT(expected, 0.0);
  // Friction is not moved by the material's elastic constants.
  EXPECT_EQ(
      covariance.row(descriptor_index(names, space::paper_descriptor_names(1).front())).norm(),
      0.0);
  // A material without standard deviations adds nothing.
  mechanics::Material datasheet = at.lab;
  datasheet.youngs_modulus_sd.reset();
  datasheet.rayleigh_stiffness_sd.reset();
  EXPECT_EQ(material_constants_covariance(model.modal, *at.design.damping, datasheet, spectrum,
                                          calibration_threshold(), names)
                .norm(),
            0.0);
  std::printf(
      "ln-descriptor slopes of the weighted mean: %.4f per ln E, %.4f per ln lambda; SD %.4f\n",
      d_modulus, d_damping, std::sqrt(covariance(w, w)));
}

}  // namespace
}  // namespace nibrig::model::design
