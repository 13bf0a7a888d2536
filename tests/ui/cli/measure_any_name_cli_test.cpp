// `nibrig measure` on recordings named anything (copies of real files in a scratch folder): the
// tool and surface from --tool/--surface, the kind from the header or --kind, and the same
// descriptors as under the file's documented name.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tests/support/test_paths.hpp"
#include "tests/ui/cli/cli_harness.hpp"

namespace nibrig::ui::cli {
namespace {

using nibrig::test::read_json;
using test::run_cli;

std::filesystem::path piovarci() { return nibrig::test::shared_data() / "piovarci2018"; }

TEST(CliMeasureAnyName, AccelerometerFileNamedAnythingWritesTheSpectrum) {
  const auto out = nibrig::test::scratch_dir("cli_measure_any_vibration");
  const auto real = piovarci() / "vibration/arm2/arm_cryon_note.csv.gz";
  const auto copy = out / "arm_DM85_25_vero_75_1_note.csv.gz";
  std::filesystem::copy_file(real, copy);
  ASSERT_EQ(run_cli({"measure", real.string(), "--no-plots", "-o", (out / "real.json").string()}),
            0);
  ASSERT_EQ(run_cli({"measure", copy.string(), "--tool", "mixA", "--surface", "note", "--no-plots",
                     "-o", (out / "m.json").string()}),
            0);
  const auto j = read_json(out / "m.json");
  const auto expected = read_json(out / "real.json");
  EXPECT_EQ(j["tool"], "mixA");
  EXPECT_EQ(j["surface"], "note");
  // Only the label differs: the spectrum is the one the file gives under its own name.
  ASSERT_TRUE(j["amplitude_m_s2"].is_array());
  EXPECT_FALSE(j["amplitude_m_s2"].empty());
  EXPECT_EQ(j["frequencies_hz"], expected["frequencies_hz"]);
  EXPECT_EQ(j["speeds_mm_s"], expected["speeds_mm_s"]);
  EXPECT_EQ(j["amplitude_m_s2"], expected["amplitude_m_s2"]);
}

TEST(CliMeasureAnyName, FrictionFileNamedAnythingIsKnownByItsHeader) {
  const auto out = nibrig::test::scratch_dir("cli_measure_any_friction");
  const auto real = piovarci() / "friction/printed/DM851_note_2.2N_13.3_1.csv.gz";
  const auto copy = out / "run7.csv.gz";
  std::filesystem::copy_file(real, copy);
  ASSERT_EQ(run_cli({"measure", real.string(), "--no-plots", "-o", (out / "real.json").string()}),
            0);
  ASSERT_EQ(run_cli({"measure", copy.string(), "--tool", "mixA", "--surface", "note", "--load",
                     "2.2", "--lever", "13.3", "--no-plots", "-o", (out / "m.json").string()}),
            0);
  const auto j = read_json(out / "m.json");
  EXPECT_EQ(j["kind"], "friction");
  EXPECT_EQ(j["tool"], "mixA");
  // Same counts, same load and lever as the documented name: the same mu to rounding.
  EXPECT_NEAR(j["mu"].get<double>(), read_json(out / "real.json")["mu"].get<double>(), 1e-12);
}

TEST(CliMeasureAnyName, FrictionWithoutTheLeverSaysWhatToState) {
  const auto out = nibrig::test::scratch_dir("cli_measure_any_lever");
  std::filesystem::copy_file(piovarci() / "friction/printed/DM851_note_2.2N_13.3_1.csv.gz",
                             out / "run7.csv.gz");
  ::testing::internal::CaptureStderr();
  const int code = run_cli({"measure", (out / "run7.csv.gz").string(), "--tool", "mixA",
                            "--surface", "note", "--no-plots", "-o", (out / "m.json").string()});
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(code, 0);
  EXPECT_NE(err.find("run7.csv.gz"), std::string::npos) << err;
  EXPECT_NE(err.find("lever factor"), std::string::npos) << err;
  EXPECT_FALSE(std::filesystem::exists(out / "m.json"));
}

TEST(CliMeasureAnyName, KindOverridesWhatTheNameSuggests) {
  const auto out = nibrig::test::scratch_dir("cli_measure_any_kind");
  // "_2.2N_" makes the name look like a friction file; the content is an accelerometer's.
  const auto copy = out / "cryon_note_2.2N_1_1.csv.gz";
  std::filesystem::copy_file(piovarci() / "vibration/arm2/arm_cryon_note.csv.gz", copy);
  ::testing::internal::CaptureStderr();
  EXPECT_NE(run_cli({"measure", copy.string(), "--no-plots", "-o", (out / "m.json").string()}), 0);
  ::testing::internal::GetCapturedStderr();
  ASSERT_EQ(run_cli({"measure", copy.string(), "--kind", "accelerometer", "--tool", "cryon",
                     "--surface", "note", "--no-plots", "-o", (out / "m.json").string()}),
            0);
  EXPECT_TRUE(read_json(out / "m.json")["amplitude_m_s2"].is_array());
}

}  // namespace
}  // namespace nibrig::ui::cli
