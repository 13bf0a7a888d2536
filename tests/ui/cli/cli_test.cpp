// End-to-end tests of the `nibrig` command on real recordings, each run as the built `nibrig` in a
// child process (cli_harness.hpp).
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/support/test_paths.hpp"
#include "tests/ui/cli/cli_harness.hpp"

namespace nibrig::ui::cli {
namespace {

using nibrig::test::is_png;
using nibrig::test::read_json;
using test::run_cli;

TEST(Cli, MeasureFrictionWritesMuAndFigures) {
  const auto out = nibrig::test::scratch_dir("cli_measure_friction");
  const auto file =
      nibrig::test::shared_data() / "piovarci2018/friction/real_tools/p2h_office_2.2N_14_1.csv.gz";
  ASSERT_EQ(run_cli({"measure", file.string(), "-o", (out / "m.json").string()}), 0);
  const auto j = read_json(out / "m.json");
  EXPECT_EQ(j["kind"], "friction");
  EXPECT_EQ(j["tool"], "p2h");
  // The paper reports μ between 0.13 and 0.33 for its pairs; a wide margin since the paper's
  // numbers come from a different contact window.
  EXPECT_GT(j["mu"].get<double>(), 0.05);
  EXPECT_LT(j["mu"].get<double>(), 0.6);
  EXPECT_LE(j["mu_ci95"][0].get<double>(), j["mu"].get<double>());
  EXPECT_GE(j["mu_ci95"][1].get<double>(), j["mu"].get<double>());
  EXPECT_TRUE(is_png(out / "p2h_office_2.2N_14_1_mu_by_speed.png"));
  EXPECT_TRUE(is_png(out / "p2h_office_2.2N_14_1_friction_trace.png"));
}

TEST(Cli, MeasureVibrationWritesTheVelocityBinnedSpectrumKeys) {
  const auto out = nibrig::test::scratch_dir("cli_measure_vibration");
  const auto file =
      nibrig::test::shared_data() / "piovarci2018/vibration/prints/arm_plain_DM85_4_office.csv.gz";
  ASSERT_EQ(run_cli({"measure", file.string(), "-o", (out / "v.json").string()}), 0);
  const auto j = read_json(out / "v.json");
  const auto& f = j["frequencies_hz"];
  const auto& s = j["speeds_mm_s"];
  const auto& a = j["amplitude_m_s2"];
  ASSERT_TRUE(f.is_array() && s.is_array() && a.is_array());
  ASSERT_EQ(a.size(), s.size());
  for (const auto& row : a) ASSERT_EQ(row.size(), f.size());
  // Speeds are in mm/s within the paper's measured range 17-250 mm/s.
  for (const auto& v : s) {
    EXPECT_GE(v.get<double>(), 17.0 - 1e-9);
    EXPECT_LE(v.get<double>(), 250.0 + 1e-9);
  }
  EXPECT_GT(j["descriptors"]["weighted_mean"].get<double>(), 0.0);
  EXPECT_TRUE(is_png(out / "arm_plain_DM85_4_office_velocity_spectrum.png"));
  EXPECT_TRUE(is_png(out / "arm_plain_DM85_4_office_spectrogram.png"));
}

TEST(Cli, ErrorsAreOneLineAndANonZeroExit) {
  ::testing::internal::CaptureStderr();
  const int code = run_cli({"measure", "/nonexistent/arm_x_y.csv.gz", "--no-plots"});
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(code, 0);
  EXPECT_NE(err.find("/nonexistent/arm_x_y.csv.gz"), std::string::npos);
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
}

TEST(Cli, MalformedRecordingNamesFileAndLine) {
  const auto dir = nibrig::test::scratch_dir("cli_malformed");
  const auto file = dir / "pen_office_2.2N_14_1.csv";
  std::ofstream(file) << "TimeStamp,X,Y,Z\n10:00:00.000,1,2,3\n10:00:00.001,1,2,abc\n";
  ::testing::internal::CaptureStderr();
  const int code = run_cli({"measure", file.string(), "--no-plots"});
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(code, 0);
  EXPECT_NE(err.find("pen_office_2.2N_14_1.csv"), std::string::npos) << err;
  EXPECT_NE(err.find("line 3"), std::string::npos) << err;
}

TEST(Cli, CatalogBuildProcessesEveryRecordingOfThePaper) {
  const auto out = nibrig::test::scratch_dir("cli_catalog");
  const auto root = nibrig::test::shared_data() / "piovarci2018";
  ASSERT_EQ(run_cli({"catalog", "build", root.string(), "-o", (out / "catalog.json").string(),
                     "--report", (out / "report").string()}),
            0);
  const auto catalog = read_json(out / "catalog.json");
  std::size_t friction = 0, vibration = 0;
  for (const auto& p : catalog["pairings"]) {
    if (p.contains("friction")) ++friction;
    if (p.contains("vibration")) ++vibration;
  }
  // Independent count from the file system: one friction file and one accelerometer file per pair
  // in this data set (each pair has a single recording of each kind).
  std::size_t friction_files = 0, vibration_files = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(root / "friction")) {
    friction_files += e.is_regular_file() ? 1 : 0;
  }
  for (const auto& e : std::filesystem::recursive_directory_iterator(root / "vibration")) {
    vibration_files += e.path().filename().string().rfind("arm_", 0) == 0 ? 1 : 0;
  }
  EXPECT_EQ(friction, friction_files);
  EXPECT_EQ(vibration, vibration_files);
  EXPECT_TRUE(is_png(out / "report" / "friction.png"));
  std::ifstream csv(out / "report" / "friction.csv");
  std::size_t lines = 0;
  for (std::string line; std::getline(csv, line);) ++lines;
  EXPECT_EQ(lines, 1 + friction_files);  // header + every friction file, none dropped
}

}  // namespace
}  // namespace nibrig::ui::cli
