// End-to-end tests of `nibrig mechanics` on bundled designs and inline bars, each run as the built
// `nibrig` in a child process (cli_harness.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "model/io/acceleration_trace.hpp"
#include "model/mechanics/beam_theory.hpp"
#include "model/mechanics/design_model.hpp"
#include "model/mechanics/ring_down.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/ui/cli/cli_harness.hpp"

namespace nibrig::ui::cli {
namespace {

using nibrig::test::is_png;
using nibrig::test::read_json;
using test::run_cli;

TEST(MechanicsCli, InlinePlainBarReportsTheKeysScriptsUseAndMatchesBeamTheory) {
  const auto out = nibrig::test::scratch_dir("cli_mech_bar");
  ::testing::internal::CaptureStdout();
  const int code =
      run_cli({"mechanics", "modes", "--bar", "0.21,0.02,0.002", "--clamp", "0.03", "--no-cutout",
               "--material", "steel", "--modes", "8", "-o", (out / "bar.json").string()});
  const std::string text = ::testing::internal::GetCapturedStdout();
  ASSERT_EQ(code, 0) << text;
  const auto j = read_json(out / "bar.json");
  EXPECT_DOUBLE_EQ(j["material"]["youngs_modulus"].get<double>(), 200e9);
  EXPECT_DOUBLE_EQ(j["material"]["density"].get<double>(), 7850);
  EXPECT_DOUBLE_EQ(j["free_length"].get<double>(), 0.18);
  EXPECT_DOUBLE_EQ(j["width"].get<double>(), 0.02);
  EXPECT_DOUBLE_EQ(j["thickness"].get<double>(), 0.002);
  ASSERT_EQ(j["modes"].size(), 8u);
  // Bending modes in the thickness direction are those the tip force (along z) drives; the first
  // three must sit within 1 % of Euler-Bernoulli (the clamp of a 10:1 wide bar stiffens it a
  // little).
  const auto beam =
      model::mechanics::cantilever_bending_frequencies(200e9, 7850, 0.18, 0.02, 0.002, 3);
  std::vector<double> bending;
  for (const auto& mode : j["modes"])
    if (std::abs(mode["tip_participation"].get<double>()) > 1.0)
      bending.push_back(mode["frequency"].get<double>());
  ASSERT_GE(bending.size(), 3u);
  for (int n = 0; n < 3; ++n)
    EXPECT_NEAR(bending[n], beam[n], 0.01 * beam[n]) << "bending mode " << n + 1;
  for (const auto& mode : j["modes"])
    EXPECT_EQ(mode["damping_ratio"].get<double>(), 0.0);  // steel: undamped
  EXPECT_TRUE(is_png(out / "bar_210_0_mm_frequency_response.png"));
}

TEST(MechanicsCli, BundledStylusDesignWithTwoMaterials) {
  const auto out = nibrig::test::scratch_dir("cli_mech_stylus");
  ::testing::internal::CaptureStdout();
  const int code =
      run_cli({"mechanics", "modes",
               (nibrig::test::assets_dir() / "designs" / "stylus_vero_dm85tip_4mm.json").string(),
               "--modes", "6", "-o", (out / "s.json").string(), "--no-plots"});
  ::testing::internal::GetCapturedStdout();
  ASSERT_EQ(code, 0);
  const auto j = read_json(out / "s.json");
  EXPECT_EQ(j["regions"]["tip"]["name"], "DM85");
  EXPECT_EQ(j["regions"]["body"]["name"], "VeroClear-Piovarci2018");
  EXPECT_EQ(j["frequency_response"]["frequencies_hz"].size(), 500u);
  for (const auto& mode : j["modes"])  // Rayleigh stiffness damping: ζ = λω/2
    EXPECT_NEAR(mode["damping_ratio"].get<double>(),
                1.25e-3 * M_PI * mode["frequency"].get<double>(), 1e-9);
}

TEST(MechanicsCli, RingDownFitsATraceAndDrawsIt) {
  namespace mech = model::mechanics;
  const auto out = nibrig::test::scratch_dir("cli_mech_ring");
  const auto materials = mech::read_material_table(nibrig::test::assets_dir() / "materials.json");
  mech::Design design =
      mech::read_design(nibrig::test::assets_dir() / "designs" / "paper_bar.json", materials);
  design.modes = 6;
  const auto truth = mech::build_design_model(design, materials);
  model::io::AccelerationTrace trace{800.0,
                                     mech::simulate_release(truth.modal, 0.05, 800.0, 2400, 0.2)};
  std::mt19937 generator(3);
  std::normal_distribution<double> noise(0.0, 0.5);
  for (double& a : trace.acceleration_m_s2)
    a = 0.5 * a + noise(generator);  // a sensor at half gain
  model::io::write_acceleration_trace(out / "ring.csv", trace);

  // The design's material is the datasheet VeroClear: the fit must move E from 2.5 to 0.45 GPa.
  const auto design_file = out / "bar.json";
  std::ofstream(design_file) << R"({"format": "nibrig-design", "version": 1, "name": "bar",
    "shape": {"kind": "bar"}, "materials": {"body": "VeroClear"}, "damping": {"rayleigh_stiffness": 1e-3},
    "mesh_size": 0.004, "modes": 6})";
  ::testing::internal::CaptureStdout();
  const int code = run_cli({"mechanics", "ringdown", (out / "ring.csv").string(),
                            design_file.string(), "-o", (out / "fit.json").string()});
  const std::string text = ::testing::internal::GetCapturedStdout();
  ASSERT_EQ(code, 0) << text;
  const auto fit = read_json(out / "fit.json");
  EXPECT_NEAR(fit["youngs_modulus"].get<double>(), 0.45e9, 0.01 * 0.45e9);
  EXPECT_NEAR(fit["rayleigh_stiffness"].get<double>(), 1.25e-3, 0.05 * 1.25e-3);
  EXPECT_NEAR(fit["gain"].get<double>(), 0.5, 0.02);
  EXPECT_TRUE(is_png(out / "ring_ring_down.png"));
}

TEST(MechanicsCli, BadDesignsFailInOneLine) {
  const auto out = nibrig::test::scratch_dir("cli_mech_bad");
  auto one_line_error = [](std::vector<std::string> args, const std::string& expected) {
    ::testing::internal::CaptureStderr();
    ::testing::internal::CaptureStdout();
    const int code = run_cli(std::move(args));
    ::testing::internal::GetCapturedStdout();
    const std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(code, 0);
    EXPECT_NE(err.find(expected), std::string::npos) << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  };
  one_line_error({"mechanics", "modes", "--bar", "0.21,0.02,-0.002"}, "thickness");
  one_line_error({"mechanics", "modes", "--bar", "0.21,0.02,0.002", "--material", "adamantium"},
                 "unknown material 'adamantium'");
  std::ofstream(out / "negative.json")
      << R"({"format": "nibrig-materials", "version": 1, "materials": [
    {"name": "soft", "youngs_modulus": -2e9, "poisson_ratio": 0.3, "density": 1000, "source": "x"}]})";
  one_line_error({"mechanics", "modes", "--bar", "0.21,0.02,0.002", "--materials",
                  (out / "negative.json").string()},
                 "Young's modulus must be positive");
  one_line_error(
      {"mechanics", "modes", "/nonexistent/nib.stl", "--tip", "0,0,0", "--sensor", "0,0,0"},
      "no such file");
}

}  // namespace
}  // namespace nibrig::ui::cli
