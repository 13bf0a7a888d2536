// The mode report written and read back: every number the modal model holds comes back as
// written (nlohmann writes the digits that read back to the same double), in the documented keys.
#include "model/mechanics/mode_report.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "model/io/finite_output.hpp"
#include "model/modal/frequency_response.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::mechanics {
namespace {

const MaterialTable& mode_report_materials() {
  static const MaterialTable table =
      read_material_table(nibrig::test::assets_dir() / "materials.json");
  return table;
}

const DesignModel& mode_report_bar() {
  static const DesignModel model = [] {
    Design design = read_design(nibrig::test::assets_dir() / "designs" / "paper_bar.json",
                                mode_report_materials());
    design.modes = 4;
    return build_design_model(design, mode_report_materials());
  }();
  return model;
}

nlohmann::json mode_report_read(const std::filesystem::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

TEST(ModeReport, RoundTripsTheModesAndTheResponseExactly) {
  const DesignModel& bar = mode_report_bar();
  const auto file = nibrig::test::scratch_dir("mode_report") / "paper_bar.json";
  write_mode_report(file, bar);
  const nlohmann::json j = mode_report_read(file);
  EXPECT_EQ(j, mode_report_json(bar));  // the file is the JSON, nothing lost on the way

  EXPECT_EQ(j.at("design").get<std::string>(), bar.design.name);
  EXPECT_EQ(j.at("material").at("name").get<std::string>(), body_material(bar).name);
  EXPECT_EQ(j.at("material").at("youngs_modulus").get<double>(), body_material(bar).youngs_modulus);
  const auto& modes = j.at("modes");
  ASSERT_EQ(modes.size(), bar.modal.size());
  for (std::size_t i = 0; i < bar.modal.size(); ++i) {
    // Shortest round-trip digits: the doubles come back bit for bit, so exact comparisons.
    EXPECT_EQ(modes[i].at("frequency").get<double>(), bar.modal.omega[i] / (2 * M_PI));
    EXPECT_EQ(modes[i].at("damping_ratio").get<double>(), bar.modal.zeta[i]);
    EXPECT_EQ(modes[i].at("tip_participation").get<double>(), bar.modal.input[i]);
    EXPECT_EQ(modes[i].at("sensor_participation").get<double>(), bar.modal.output[i]);
    const auto fractions = modes[i].at("displacement_fractions").get<std::vector<double>>();
    ASSERT_EQ(fractions.size(), 3u);
    // Shares of the mode's displacement along x, y and z: they add up to one, to rounding.
    EXPECT_NEAR(fractions[0] + fractions[1] + fractions[2], 1.0, 1e-12);
  }
  const auto frequencies = j.at("frequency_response").at("frequencies_hz").get<std::vector<double>>();
  const auto magnitude =
      j.at("frequency_response").at("magnitude_m_s2_per_N").get<std::vector<double>>();
  const auto response = modal::frequency_response(bar.modal, frequencies);
  ASSERT_EQ(magnitude.size(), response.size());
  for (std::size_t k = 0; k < response.size(); ++k) EXPECT_EQ(magnitude[k], std::abs(response[k]));
  // A plain bar? paper_bar has a cutout: no Euler-Bernoulli reference then.
  EXPECT_FALSE(j.contains("euler_bernoulli_bending_hz"));
  EXPECT_GT(j.at("free_length").get<double>(), 0.0);
}

TEST(ModeReport, RefusesANonFiniteNumberNamingTheFileAndField) {
  DesignModel broken = mode_report_bar();
  for (auto& material : broken.region_materials) material.density = std::nan("");
  const auto file = nibrig::test::scratch_dir("mode_report_nan") / "broken.json";
  try {
    write_mode_report(file, broken);
    FAIL() << "wrote a NaN";
  } catch (const io::UnwritableOutput& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("broken.json"), std::string::npos) << m;
    EXPECT_NE(m.find("density"), std::string::npos) << m;
  }
  EXPECT_FALSE(std::filesystem::exists(file));
}

}  // namespace
}  // namespace nibrig::model::mechanics
