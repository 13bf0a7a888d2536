// A surface the lab's model does not know, calibrated from tools it does know: without noise its
// forcing is recovered exactly; with the rig's noise the hidden forcing lies within the reported
// uncertainty as often as that says; one tool gives a forcing without an uncertainty; and tools
// that cannot calibrate are refused by name.
#include "model/forcing/surface_calibration.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/model/forcing/calibration_truth.hpp"

namespace nibrig::model::forcing {
namespace {

// A hidden forcing on a new surface: each cell's ln F drawn around the model's stone.
std::vector<std::vector<double>> hidden_surface_forcing(const ForcingModel& model, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, 0.5);
  auto forcing = model.surface_forcing.at("stone");
  for (auto& row : forcing)
    for (double& f : row) f *= std::exp(normal(rng));
  return forcing;
}

// The known tools (material × tip) measured on the new surface.
std::vector<ForcingExemplar> surface_reference_tools(
    const test::LabTruth& truth, const std::vector<std::vector<double>>& forcing, std::size_t count,
    unsigned seed) {
  const std::vector<std::pair<std::string, double>> tools{
      {"vero", 0.002}, {"DM85", 0.001}, {"vero", 0.004}, {"DM85", 0.004}, {"vero", 0.001}};
  std::mt19937 rng(seed);
  std::vector<ForcingExemplar> out;
  for (std::size_t i = 0; i < count; ++i) {
    const auto& [material, tip] = tools.at(i);
    out.push_back(test::simulated_print(truth, material + std::to_string(int(tip * 1e3)), material,
                                        tip, "protector2", truth.model.material_curve(material),
                                        forcing, rng));
  }
  return out;
}

TEST(SurfaceCalibration, NoiselessToolsGiveTheForcingExactly) {
  test::LabTruth truth = test::make_lab_truth(11);
  truth.noise_log = 0.0;
  const auto hidden = hidden_surface_forcing(truth.model, 12);
  const auto tools = surface_reference_tools(truth, hidden, 3, 13);
  const SurfaceCalibration c = calibrate_surface(truth.model, tools, "protector2");
  const auto& forcing = c.model.surface_forcing.at("protector2");
  for (std::size_t s = 0; s < hidden.size(); ++s)
    for (std::size_t j = 0; j < hidden[s].size(); ++j) {
      EXPECT_NEAR(std::log(forcing[s][j] / hidden[s][j]), 0.0, 1e-9) << s << " " << j;
      EXPECT_LT(c.log_forcing_se[s][j], 1e-9);
    }
  EXPECT_LT(c.residual_rms_db, 1e-6);
  EXPECT_EQ(c.model.surface_log_forcing_se.at("protector2"), c.log_forcing_se);
  EXPECT_EQ(truth.model.surface_forcing.count("protector2"), 0u);
}

// Over 20 draws of three tools on a hidden surface (1482 cells each): how often the truth lies
// within the reported standard errors. A cell's variance is pooled over ±25 Hz (about 25 bins of 2
// tools' deviations each, correlated over 5 bins: ~10 effective degrees of freedom), so the error
// over its SE is close to a t with 10: 93 % within ±2 SE and 66 % within ±1. The bounds leave a few
// percent for the pooling's bias where the tools' spread changes within the window.
TEST(SurfaceCalibration, TheHiddenForcingLiesWithinTheReportedUncertainty) {
  std::size_t within_two = 0, within_one = 0, cells = 0;
  double se_db = 0.0;
  const int draws = 20;
  for (int draw = 0; draw < draws; ++draw) {
    const test::LabTruth truth = test::make_lab_truth(400 + draw);
    const auto hidden = hidden_surface_forcing(truth.model, 500 + draw);
    const auto tools = surface_reference_tools(truth, hidden, 3, 600 + draw);
    const SurfaceCalibration c = calibrate_surface(truth.model, tools, "protector2");
    for (std::size_t s = 0; s < hidden.size(); ++s)
      for (std::size_t j = 0; j < hidden[s].size(); ++j) {
        const double z =
            std::abs(c.log_forcing[s][j] - std::log(hidden[s][j])) / c.log_forcing_se[s][j];
        within_two += z <= 2.0;
        within_one += z <= 1.0;
        ++cells;
      }
    se_db += c.rms_se_db;
  }
  const auto fraction = [&](std::size_t n) { return double(n) / double(cells); };
  std::cout << "hidden-forcing coverage over " << draws << " draws of 3 tools, " << cells
            << " cells: within 2 SE " << fraction(within_two) << ", within 1 SE "
            << fraction(within_one) << "; mean RMS SE " << se_db / draws << " dB\n";
  EXPECT_GE(fraction(within_two), 0.88);
  EXPECT_LE(fraction(within_one), 0.80);
}

TEST(SurfaceCalibration, OneToolGivesTheForcingButNoUncertainty) {
  const test::LabTruth truth = test::make_lab_truth(21);
  const auto hidden = hidden_surface_forcing(truth.model, 22);
  const SurfaceCalibration c =
      calibrate_surface(truth.model, surface_reference_tools(truth, hidden, 1, 23), "protector2");
  EXPECT_TRUE(c.log_forcing_se.empty());
  EXPECT_EQ(c.rms_se_db, 0.0);
  EXPECT_EQ(c.model.surface_log_forcing_se.count("protector2"), 0u);
  EXPECT_EQ(c.model.surface_forcing.count("protector2"), 1u);
  EXPECT_LT(c.residual_rms_db, 1e-9);  // one tool: the forcing is its own data
}

TEST(SurfaceCalibration, ToolsThatCannotCalibrateAreRefusedByName) {
  const test::LabTruth truth = test::make_lab_truth(31);
  const auto hidden = hidden_surface_forcing(truth.model, 32);
  const auto tools = surface_reference_tools(truth, hidden, 3, 33);
  const auto refused = [&](const std::vector<ForcingExemplar>& t, const std::string& surface,
                           const std::string& expected) {
    try {
      calibrate_surface(truth.model, t, surface);
      ADD_FAILURE() << "expected a refusal mentioning " << expected;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  };
  refused({}, "protector2", "no tools");
  refused(tools, "stone", "already has it");
  refused(tools, "glass2", "vero2 on protector2 was measured on another surface");
  auto twice = tools;
  twice.push_back(tools[0]);
  refused(twice, "protector2", "vero2 is given twice");
  auto unknown = tools;
  unknown[1].material = "pla";
  refused(unknown, "protector2", "no curve for material 'pla'");
  auto silent = tools;
  for (auto& t : silent) t.measured.amplitude_m_s2[2][7] = 0.0;
  refused(silent, "protector2", "no tool has a positive amplitude");
}

}  // namespace
}  // namespace nibrig::model::forcing
