// End-to-end tests of `nibrig forcing calibrate-material|calibrate-surface` on the bundled
// catalog, each run as the built `nibrig` in a child process (cli_harness.hpp): the check on the
// catalog gives its numbers (--json) beside the repeatability, writes the calibrated model with its
// errors and stores it by name; a calibration against a stored model finds it by name; an output
// that is an input and a name stored already are refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

#include "model/forcing/forcing_file.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/ui/cli/cli_harness.hpp"

namespace nibrig::ui::cli {
namespace {

using nibrig::test::with_coarse;
using test::read_json;
using test::run_cli;

// 20·log10(e): the JSON's dB from the model file's natural-log gains.
constexpr double kDbPerNeper = 8.685889638065035;

bool finite_positive(const nlohmann::json& value) {
  return value.is_number() && std::isfinite(value.get<double>()) && value.get<double>() > 0.0;
}

// The entry of `rows` for a tool on a surface, or null. (The tests keep their JSON non-const:
// a missing key then reads as null and fails the check instead of being undefined.)
nlohmann::json print_row(const nlohmann::json& rows, const std::string& tool,
                         const std::string& surface) {
  for (const auto& row : rows)
    if (row["tool"] == tool && row["surface"] == surface) return row;
  return nullptr;
}

// The user store of calibrated models pointed at a scratch folder for one test.
class ForcingCalibrateCli : public ::testing::Test {
 protected:
  void SetUp() override {
    out_ = nibrig::test::scratch_dir("cli_forcing_calibrate");
    ::setenv("NIBRIG_FORCING_MODELS", (out_ / "store").c_str(), 1);
  }
  void TearDown() override { ::unsetenv("NIBRIG_FORCING_MODELS"); }

  // Runs the command, capturing stdout and stderr; returns the exit code.
  int run(const std::vector<std::string>& args) {
    ::testing::internal::CaptureStdout();
    ::testing::internal::CaptureStderr();
    const int code = run_cli(args);
    text_ = ::testing::internal::GetCapturedStdout();
    error_ = ::testing::internal::GetCapturedStderr();
    return code;
  }

  std::filesystem::path out_;
  std::string text_, error_;
};

TEST_F(ForcingCalibrateCli, AMaterialTakenAsNewIsCalibratedWrittenAndStored) {
  const auto file = out_ / "dm95.json";
  const auto numbers_file = out_ / "dm95_check.json";
  ASSERT_EQ(
      run(with_coarse({"forcing", "calibrate-material", "--material", "DM95", "-o", file.string(),
                       "--save", "lab-DM95", "--json", numbers_file.string()})),
      0)
      << text_ << error_;
  auto check = read_json(numbers_file);
  // DM95 taken as new: the check, calibrated from its 1 and 4 mm prints (DM951, DM954) on the six
  // surfaces. Counts: exact.
  EXPECT_EQ(check["mode"], "check") << check.dump(1);
  EXPECT_EQ(check["material"], "DM95");
  EXPECT_EQ(check["calibration"]["prints"], 2) << check.dump(1);
  EXPECT_EQ(check["calibration"]["exemplars"], 12) << check.dump(1);
  // The repeatability from the nail prints recorded twice: some pair, a positive RMS dB difference
  // (any finite value > 0: two recordings never agree exactly).
  ASSERT_TRUE(check["repeatability"].is_object()) << check.dump(1);
  EXPECT_TRUE(finite_positive(check["repeatability"]["rms_db"])) << check["repeatability"];
  EXPECT_GE(check["repeatability"]["pairs"].get<int>(), 1);
  // The 2 prints predicted (DM952 on glass and protector; the rest in sample), and the mean of
  // their calibrated errors is their rows' mean: finite, positive, equal within 1e-9 dB (both
  // from the same doubles; only the summation's rounding differs).
  ASSERT_TRUE(check["means"].is_object()) << check.dump(1);
  EXPECT_EQ(check["means"]["prints"], 2);
  double sum = 0.0;
  int predicted = 0;
  for (const auto& row : check["print_errors"])
    if (!row["in_sample"].get<bool>()) {
      sum += row["calibrated_rms_db"].get<double>();
      ++predicted;
    }
  EXPECT_EQ(predicted, 2) << check["print_errors"];
  EXPECT_TRUE(finite_positive(check["means"]["calibrated_db"])) << check["means"];
  EXPECT_NEAR(check["means"]["calibrated_db"].get<double>(), sum / 2.0, 1e-9);
  // The curve per knot as the written model holds it, with the fit of everything's beside it:
  // the JSON and the file both hold the doubles to round trip, so 1e-9 dB is rounding alone.
  const auto model = model::forcing::read_forcing_model(file);
  const auto& curve = check["calibration"]["curve"];
  ASSERT_EQ(curve.size(), 11u) << check["calibration"];
  for (std::size_t k = 0; k < curve.size(); ++k) {
    EXPECT_NEAR(curve[k]["gain_db"].get<double>(), kDbPerNeper * model.material_curve("DM95")[k],
                1e-9);
    EXPECT_NEAR(curve[k]["se_db"].get<double>(),
                kDbPerNeper * model.material_log_gain_se.at("DM95")[k], 1e-9);
    EXPECT_TRUE(std::isfinite(curve[k]["full_fit_gain_db"].get<double>())) << curve[k];
  }
  // The model without DM95 (vero, DM85, teflon) with DM95 calibrated and its 11 knots' errors.
  EXPECT_EQ(model.material_log_gain.size(), 4u);
  ASSERT_EQ(model.material_log_gain_se.count("DM95"), 1u);
  EXPECT_EQ(model.material_log_gain_se.at("DM95").size(), 11u);
  EXPECT_FALSE(model.held_out_descriptor_errors.empty());
  const auto stored = out_ / "store" / "lab-DM95.json";
  EXPECT_EQ(model::forcing::read_forcing_model(stored).material_log_gain_se,
            model.material_log_gain_se);

  // Stored again under the same name: refused, the stored model kept.
  EXPECT_NE(run(with_coarse(
                {"forcing", "calibrate-material", "--material", "DM95", "--save", "lab-DM95"})),
            0);
  EXPECT_NE(error_.find("a forcing model named 'lab-DM95' is stored already"), std::string::npos)
      << error_;

  // A lab's model without DM95 (the file above, its DM95 curve taken out): DM95 calibrated against
  // it from its 1 and 4 mm prints, its 2 mm prints predicted, the result written with its errors.
  std::ifstream in(file);
  auto json = nlohmann::json::parse(in);
  auto& curves = json["material_curves"];
  curves.erase(std::remove_if(curves.begin(), curves.end(),
                              [](const auto& c) { return c["material"] == "DM95"; }),
               curves.end());
  std::ofstream(out_ / "without.json") << json.dump();
  const auto again = out_ / "again.json";
  const auto against_file = out_ / "dm95_against.json";
  ASSERT_EQ(run(with_coarse({"forcing", "calibrate-material", "--material", "DM95", "--forcing",
                             (out_ / "without.json").string(), "-o", again.string(), "--json",
                             against_file.string()})),
            0)
      << text_ << error_;
  auto against = read_json(against_file);
  EXPECT_EQ(against["mode"], "against_model") << against.dump(1);
  EXPECT_EQ(against["material"], "DM95");
  // DM952 on glass among the prints predicted, with the check's error for it: the same held model
  // (through the file's round-trip digits) and prints, so equal within 1e-9 dB.
  const auto dm952 = print_row(against["predicted_prints"], "DM952", "glass");
  ASSERT_TRUE(dm952.is_object()) << against["predicted_prints"];
  EXPECT_TRUE(finite_positive(dm952["rms_db"])) << dm952;
  const auto checked = print_row(check["print_errors"], "DM952", "glass");
  ASSERT_TRUE(checked.is_object()) << check["print_errors"];
  EXPECT_NEAR(dm952["rms_db"].get<double>(), checked["calibrated_rms_db"].get<double>(), 1e-9);
  EXPECT_EQ(against["predicted_prints"].size(), 2u) << against["predicted_prints"];
  // Against the same held model and prints, the same curve as the check's (to the file's digits).
  const auto recalibrated = model::forcing::read_forcing_model(again);
  for (std::size_t k = 0; k < 11; ++k)
    EXPECT_NEAR(recalibrated.material_curve("DM95")[k], model.material_curve("DM95")[k], 1e-12);
}

TEST_F(ForcingCalibrateCli, ACalibrationAgainstAStoredModelFindsItByName) {
  // A surface calibrated from three of its tools against the model without it, stored; then DM85
  // cannot be calibrated against it (the model has DM85), a name not stored is refused, and the
  // surface is calibrated against that model with it taken out, found by name.
  const auto study_file = out_ / "glass_study.json";
  ASSERT_EQ(run(with_coarse({"forcing", "calibrate-surface", "--surface", "glass", "--tools",
                             "vero2,DM851,DM954", "--subsets", "5", "--save", "no-glass", "--json",
                             study_file.string()})),
            0)
      << text_ << error_;
  auto study = read_json(study_file);
  EXPECT_EQ(study["mode"], "study") << study.dump(1);
  EXPECT_EQ(study["surface"], "glass");
  // The calibration's SE is within the repeatability from 2 tools: a count, exact; the step of 2
  // tools has an SE at most the repeatability (the comparison the count is made by), 1 tool none.
  ASSERT_TRUE(study["repeatability"].is_object()) << study.dump(1);
  EXPECT_EQ(study["fewest_tools_se_within_repeatability"], 2) << study.dump(1);
  ASSERT_GE(study["steps"].size(), 2u) << study.dump(1);
  EXPECT_TRUE(study["steps"][0]["se_rms_db"].is_null()) << study["steps"][0];
  EXPECT_TRUE(finite_positive(study["steps"][1]["se_rms_db"])) << study["steps"][1];
  EXPECT_LE(study["steps"][1]["se_rms_db"].get<double>(),
            study["repeatability"]["rms_db"].get<double>());
  // Written: glass calibrated from the 3 tools asked for, with a finite positive SE.
  ASSERT_TRUE(study["written"].is_object()) << study.dump(1);
  EXPECT_EQ(study["written"]["tools"].size(), 3u) << study["written"];
  EXPECT_TRUE(finite_positive(study["written"]["se_rms_db"])) << study["written"];
  const auto stored = model::forcing::read_forcing_model(out_ / "store" / "no-glass.json");
  ASSERT_EQ(stored.surface_log_forcing_se.count("glass"), 1u);

  EXPECT_NE(run(with_coarse(
                {"forcing", "calibrate-material", "--material", "DM85", "--forcing", "no-glass"})),
            0);
  EXPECT_NE(error_.find("already has a curve"), std::string::npos) << error_;
  EXPECT_NE(run(with_coarse(
                {"forcing", "calibrate-surface", "--surface", "glass", "--forcing", "not-stored"})),
            0);
  EXPECT_NE(error_.find("no forcing model file 'not-stored'"), std::string::npos) << error_;
  EXPECT_NE(error_.find("stored: no-glass"), std::string::npos) << error_;

  // That model with glass taken out, stored by name: glass calibrated against it from the same
  // tools gives the written calibration's SE (the same held model, through the file's round-trip
  // digits: 1e-9 dB is rounding alone) and an in-sample fit per tool.
  auto without = read_json(out_ / "store" / "no-glass.json");
  auto& surfaces = without["surfaces"];
  surfaces.erase(std::remove_if(surfaces.begin(), surfaces.end(),
                                [](const auto& s) { return s["id"] == "glass"; }),
                 surfaces.end());
  std::ofstream(out_ / "store" / "without-glass.json") << without.dump();
  const auto against_file = out_ / "glass_against.json";
  ASSERT_EQ(run(with_coarse({"forcing", "calibrate-surface", "--surface", "glass", "--tools",
                             "vero2,DM851,DM954", "--forcing", "without-glass", "--json",
                             against_file.string()})),
            0)
      << text_ << error_;
  auto against = read_json(against_file);
  EXPECT_EQ(against["mode"], "against_model") << against.dump(1);
  ASSERT_TRUE(finite_positive(against["se_rms_db"])) << against.dump(1);
  EXPECT_NEAR(against["se_rms_db"].get<double>(), study["written"]["se_rms_db"].get<double>(),
              1e-9);
  ASSERT_EQ(against["tools"].size(), 3u) << against.dump(1);
  for (const auto& t : against["tools"]) EXPECT_TRUE(finite_positive(t["rms_db"])) << t;
}

TEST_F(ForcingCalibrateCli, AnOutputThatIsAnInputIsRefused) {
  const auto model_file = out_ / "model.json";
  ASSERT_EQ(run(with_coarse({"forcing", "calibrate-surface", "--surface", "paperlike", "--subsets",
                             "3", "-o", model_file.string()})),
            0)
      << error_;
  const auto before = model::forcing::read_forcing_model(model_file).surface_forcing;
  // Calibrating against the file and writing over it: refused before any work.
  EXPECT_NE(run(with_coarse({"forcing", "calibrate-surface", "--surface", "paperlike", "--forcing",
                             model_file.string(), "-o", model_file.string()})),
            0);
  EXPECT_NE(error_.find("is also --forcing of this command"), std::string::npos) << error_;
  EXPECT_EQ(model::forcing::read_forcing_model(model_file).surface_forcing, before);
}

}  // namespace
}  // namespace nibrig::ui::cli
