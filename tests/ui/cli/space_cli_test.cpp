// End-to-end tests of `nibrig space fit|predict`, each run as the built `nibrig` in a child process
// (cli_harness.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>
#include <sstream>

#include "model/io/triplets.hpp"
#include "model/space/objective.hpp"
#include "model/space/space_file.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/ui/cli/cli_harness.hpp"
#include "tests/ui/cli/line_judgments.hpp"

namespace nibrig::ui::cli {
namespace {

using test::run_cli;

// Every triplet of six stimuli on a line (0, 1, ..., 5 units) judged 10 times by the paper's
// observer.
std::filesystem::path simulated_judgments(const std::filesystem::path& dir) {
  return test::write_line_judgments(dir / "judgments.csv",
                                    Eigen::RowVectorXd::LinSpaced(6, 0.0, 5.0), 10, 5);
}

TEST(SpaceCli, FitThenPredictGivesTheModelsProbabilitiesInInputOrder) {
  const auto dir = nibrig::test::scratch_dir("cli_space");
  const auto judgments = simulated_judgments(dir);
  ::testing::internal::CaptureStdout();
  ASSERT_EQ(run_cli({"space", "fit", judgments.string(), "--dims", "1", "--starts", "4", "-o",
                     (dir / "space.json").string()}),
            0);
  ASSERT_EQ(run_cli({"space", "predict", (dir / "space.json").string(), judgments.string(), "-o",
                     (dir / "p.csv").string()}),
            0);
  ::testing::internal::GetCapturedStdout();

  const auto space = model::space::read_space_file(dir / "space.json");
  ASSERT_EQ(space.coordinates.rows(), 1);
  // The recovered line keeps the order of the truth (up to direction): a rank check on 6 points.
  const double direction = space.coordinates(0, 5) > space.coordinates(0, 0) ? 1.0 : -1.0;
  for (int i = 0; i + 1 < 6; ++i)
    EXPECT_LT(direction * space.coordinates(0, i), direction * space.coordinates(0, i + 1));

  const auto queries = model::io::read_triplet_csv(judgments);
  std::ifstream csv(dir / "p.csv");
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "reference,a,b,p_first");
  for (const auto& t : queries.triplets) {
    ASSERT_TRUE(std::getline(csv, line));
    std::stringstream row(line);
    std::string r, a, b, p;
    std::getline(row, r, ','), std::getline(row, a, ','), std::getline(row, b, ','),
        std::getline(row, p, ',');
    EXPECT_EQ(r, queries.stimuli[t.reference]);
    EXPECT_EQ(a, queries.stimuli[t.a]);
    EXPECT_EQ(b, queries.stimuli[t.b]);
    // Written with 10 significant digits.
    EXPECT_NEAR(std::stod(p),
                model::space::probability_first(model::space::JudgmentModel{}, space.coordinates,
                                                t.reference, t.a, t.b),
                1e-9);
  }
  EXPECT_FALSE(std::getline(csv, line));

  // Queries need no responses: a list of triplets with both counts 0 is predicted too.
  std::ofstream(dir / "queries.csv")
      << "reference,a,b,count_a,count_b\ns0,s1,s5,0,0\ns5,s4,s0,0,0\n";
  ::testing::internal::CaptureStdout();
  ASSERT_EQ(
      run_cli({"space", "predict", (dir / "space.json").string(), (dir / "queries.csv").string()}),
      0);
  const std::string out = ::testing::internal::GetCapturedStdout();
  EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), 3) << out;
  EXPECT_NE(out.find("s0,s1,s5,"), std::string::npos) << out;
}

TEST(SpaceCli, UnknownStimulusAndUnsupportedLambdaFailInOneLine) {
  const auto dir = nibrig::test::scratch_dir("cli_space_bad");
  const auto judgments = simulated_judgments(dir);
  ::testing::internal::CaptureStdout();
  ASSERT_EQ(run_cli({"space", "fit", judgments.string(), "--dims", "1", "--starts", "2", "-o",
                     (dir / "space.json").string()}),
            0);
  ::testing::internal::GetCapturedStdout();
  std::ofstream(dir / "other.csv") << "reference,a,b,count_a,count_b\ns0,s1,zebra,0,0\n";
  ::testing::internal::CaptureStderr();
  EXPECT_NE(
      run_cli({"space", "predict", (dir / "space.json").string(), (dir / "other.csv").string()}),
      0);
  std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(err.find("stimulus 'zebra' is not in"), std::string::npos) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  ::testing::internal::CaptureStderr();
  EXPECT_NE(run_cli({"space", "fit", judgments.string(), "--lambda", "1"}), 0);
  err = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(err.find("--descriptors"), std::string::npos) << err;
}

}  // namespace
}  // namespace nibrig::ui::cli
