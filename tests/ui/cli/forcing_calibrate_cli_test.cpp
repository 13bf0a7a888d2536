// End-to-end tests of `nibrig forcing calibrate-material|calibrate-surface` on the bundled
// catalog, each run as the built `nibrig` in a child process (cli_harness.hpp): the check on the
// catalog prints its table beside the repeatability, writes the calibrated model with its errors
// and stores it by name; a calibration against a stored model finds it by name; an output that is
// an input and a name stored already are refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

#include "model/forcing/forcing_file.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/ui/cli/cli_harness.hpp"

namespace nibrig::ui::cli {
namespace {

using nibrig::test::with_coarse;
using test::run_cli;

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
  ASSERT_EQ(run(with_coarse({"forcing", "calibrate-material", "--material", "DM95", "-o",
                             file.string(), "--save", "lab-DM95"})),
            0)
      << text_ << error_;
  EXPECT_NE(text_.find("DM95 taken as new"), std::string::npos) << text_;
  EXPECT_NE(text_.find("the measurement's repeatability: "), std::string::npos) << text_;
  EXPECT_NE(text_.find("mean over the 2 prints predicted: calibrated "), std::string::npos)
      << text_;
  EXPECT_NE(text_.find("DM95 (fit of everything)"), std::string::npos) << text_;
  const auto model = model::forcing::read_forcing_model(file);
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
  ASSERT_EQ(run(with_coarse({"forcing", "calibrate-material", "--material", "DM95", "--forcing",
                             (out_ / "without.json").string(), "-o", again.string()})),
            0)
      << text_ << error_;
  EXPECT_NE(text_.find("DM95 calibrated against"), std::string::npos) << text_;
  EXPECT_NE(text_.find("DM952       glass"), std::string::npos) << text_;
  EXPECT_NE(text_.find("(predicted)"), std::string::npos) << text_;
  // Against the same held model and prints, the same curve as the check's (to the file's digits).
  const auto recalibrated = model::forcing::read_forcing_model(again);
  for (std::size_t k = 0; k < 11; ++k)
    EXPECT_NEAR(recalibrated.material_curve("DM95")[k], model.material_curve("DM95")[k], 1e-12);
}

TEST_F(ForcingCalibrateCli, ACalibrationAgainstAStoredModelFindsItByName) {
  // A surface calibrated from three of its tools against the model without it, stored; then DM85
  // cannot be calibrated against it (the model has DM85), and DM95's prints can be predicted.
  ASSERT_EQ(run(with_coarse({"forcing", "calibrate-surface", "--surface", "glass", "--tools",
                             "vero2,DM851,DM954", "--subsets", "5", "--save", "no-glass"})),
            0)
      << text_ << error_;
  EXPECT_NE(text_.find("glass taken as new"), std::string::npos) << text_;
  EXPECT_NE(text_.find("the calibration's SE is within the repeatability from 2 tools"),
            std::string::npos)
      << text_;
  EXPECT_NE(text_.find("written: glass calibrated from 3 tools"), std::string::npos) << text_;
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
