// `nibrig space fit --model NAME|auto` and what a space's judgment model does to `space predict`.
#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <sstream>

#include "model/io/triplets.hpp"
#include "model/space/judgment_model.hpp"
#include "model/space/model_choice.hpp"
#include "model/space/space_file.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/ui/cli/cli_harness.hpp"
#include "tests/ui/cli/line_judgments.hpp"

namespace nibrig::ui::cli {
namespace {

using test::run_cli;
namespace space = model::space;

// Every triplet of eight stimuli on a line (0, 0.8, ..., 5.6 units) judged 12 times by an observer
// who answers at random a fifth of the time.
std::filesystem::path lapsing_judgments(const std::filesystem::path& dir) {
  space::JudgmentModel observer;
  observer.family.lapse = true;
  observer.lapse = 0.2;
  return test::write_line_judgments(dir / "judgments.csv",
                                    Eigen::RowVectorXd::LinSpaced(8, 0.0, 5.6), 12, 9, observer);
}

TEST(SpaceModelCli, AutoChoosesByCrossValidationAndRecordsWhy) {
  const auto dir = nibrig::test::scratch_dir("cli_space_model_auto");
  const auto judgments = lapsing_judgments(dir);
  ::testing::internal::CaptureStdout();
  ASSERT_EQ(run_cli({"space", "fit", judgments.string(), "--dims", "1", "--starts", "2", "--model",
                     "auto", "--models", "student-t,probit+lapse", "--folds", "4", "-o",
                     (dir / "space.json").string()}),
            0);
  const std::string out = ::testing::internal::GetCapturedStdout();
  const auto s = space::read_space_file(dir / "space.json");
  // The paper's probit is scored beside the two asked for.
  ASSERT_EQ(s.model_scores.size(), 3u);
  EXPECT_EQ(s.model_scores[0].family, "probit");
  EXPECT_NE(s.model_reason.find("4-fold cross-validation of 3 models"), std::string::npos)
      << s.model_reason;
  // A fifth of the answers at random: the lapse is found and fitted near it (12 answers × 168
  // triplets; its standard error is a few hundredths).
  EXPECT_EQ(space::family_name(s.model.family), "probit+lapse") << out;
  EXPECT_NEAR(s.model.lapse, 0.2, 0.07);
  const auto* chosen = space::score_of(s.model_scores, s.model.family);
  ASSERT_NE(chosen, nullptr);
  EXPECT_LT(chosen->log_loss, s.model_scores[0].log_loss);

  // Predictions follow the file's model: a lapse keeps every answer at least lapse/2 likely.
  std::ofstream(dir / "far.csv") << "reference,a,b,count_a,count_b\ns0,s7,s1,0,0\n";
  ::testing::internal::CaptureStdout();
  ASSERT_EQ(
      run_cli({"space", "predict", (dir / "space.json").string(), (dir / "far.csv").string()}), 0);
  const std::string p = ::testing::internal::GetCapturedStdout();
  const double far = std::stod(p.substr(p.rfind(',') + 1));
  EXPECT_NEAR(far, space::probability_first(s.model, s.coordinates, 0, 7, 1), 1e-9);
  EXPECT_GE(far, 0.5 * s.model.lapse - 1e-9);
}

TEST(SpaceModelCli, AGivenModelIsFittedAndAWrongNameIsRefused) {
  const auto dir = nibrig::test::scratch_dir("cli_space_model_given");
  const auto judgments = lapsing_judgments(dir);
  ::testing::internal::CaptureStdout();
  ASSERT_EQ(run_cli({"space", "fit", judgments.string(), "--dims", "1", "--starts", "2", "--model",
                     "student-t+noise", "-o", (dir / "space.json").string()}),
            0);
  ::testing::internal::GetCapturedStdout();
  const auto s = space::read_space_file(dir / "space.json");
  EXPECT_EQ(space::family_name(s.model.family), "student-t+noise");
  EXPECT_EQ(s.model.log_noise.size(), 8);
  EXPECT_TRUE(s.model_scores.empty());
  EXPECT_NE(s.model_reason.find("given"), std::string::npos) << s.model_reason;

  ::testing::internal::CaptureStderr();
  EXPECT_NE(run_cli({"space", "fit", judgments.string(), "--model", "probit+noise+lapse"}), 0);
  std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(err.find("--model"), std::string::npos) << err;
  EXPECT_NE(err.find("probit+lapse+noise"), std::string::npos) << err;  // the names that exist
  ::testing::internal::CaptureStderr();
  EXPECT_NE(run_cli({"space", "fit", judgments.string(), "--models", "student-t"}), 0);
  err = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(err.find("--models: "), std::string::npos) << err;
  EXPECT_NE(err.find("auto"), std::string::npos) << err;
}

}  // namespace
}  // namespace nibrig::ui::cli
