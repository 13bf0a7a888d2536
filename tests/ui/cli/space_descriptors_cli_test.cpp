// End-to-end tests of the descriptor side of `nibrig space`: fit tied to catalog descriptors with
// bootstrap regions and a plot, `embed`, `evaluate` and `predict` with tools placed from their
// descriptors, and `validate`.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>
#include <sstream>

#include "model/io/catalog_file.hpp"
#include "model/io/triplets.hpp"
#include "model/space/catalog_descriptors.hpp"
#include "model/space/objective.hpp"
#include "model/space/space_file.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/ui/cli/cli_harness.hpp"

namespace nibrig::ui::cli {
namespace {

using test::run_cli;

struct Study {
  std::filesystem::path catalog, judgments, new_tool_judgments;
  std::vector<std::string> names;  // the 13 pairings; the last is never judged in `judgments`
};

// A simulated observer whose space is the standardised descriptors (1.5 units per standard
// deviation): 12 catalog pairings judged on every triplet 6 times, and separately 30 triplets that
// involve a 13th pairing, so that placing it from its descriptors can be scored.
Study descriptor_study(const std::filesystem::path& dir) {
  Study s;
  s.catalog = nibrig::test::assets_dir() / "default_catalog.json";
  const auto catalog = model::io::read_catalog(s.catalog);
  const auto all = model::space::descriptors_of_catalog(catalog, s.catalog, 2);
  for (Eigen::Index i = 0; i < 13; ++i) s.names.push_back(all.rows[static_cast<std::size_t>(i * 4)]);
  Eigen::MatrixXd values(13, 2);
  for (Eigen::Index i = 0; i < 13; ++i) values.row(i) = all.values.row(i * 4);
  const Eigen::RowVectorXd mean = values.colwise().mean();
  const Eigen::RowVectorXd sd =
      ((values.rowwise() - mean).array().square().colwise().sum() / 12.0).sqrt();
  const Eigen::MatrixXd truth =
      (1.5 * ((values.rowwise() - mean).array().rowwise() / sd.array())).matrix().transpose();
  std::mt19937 generator(3);
  auto judge = [&](std::size_t r, std::size_t a, std::size_t b, int n) {
    std::binomial_distribution<int> observer(n, model::space::probability_first(model::space::JudgmentModel{}, truth, r, a, b));
    model::io::Triplet t;
    t.reference = r, t.a = a, t.b = b;
    t.count_a = observer(generator);
    t.count_b = n - t.count_a;
    return t;
  };
  model::io::TripletSet judged, fresh;
  judged.stimuli = fresh.stimuli = s.names;
  for (std::size_t r = 0; r < 12; ++r)
    for (std::size_t a = 0; a < 12; ++a)
      for (std::size_t b = a + 1; b < 12; ++b)
        if (a != r && b != r) judged.triplets.push_back(judge(r, a, b, 6));
  for (std::size_t k = 0; k < 30; ++k) {  // the new tool as reference or candidate
    const std::size_t x = k % 12, y = (k * 5 + 1) % 12 == x ? (x + 1) % 12 : (k * 5 + 1) % 12;
    fresh.triplets.push_back(k % 2 ? judge(12, x, y, 12) : judge(x, 12, y, 12));
  }
  s.judgments = dir / "judged.csv";
  s.new_tool_judgments = dir / "new_tool.csv";
  model::io::write_triplet_csv(s.judgments, judged);
  model::io::write_triplet_csv(s.new_tool_judgments, fresh);
  return s;
}

TEST(SpaceCliDescriptors, FitPlaceEvaluateAndPredictNewTools) {
  const auto dir = nibrig::test::scratch_dir("cli_space_descriptors");
  const Study s = descriptor_study(dir);
  const auto space_file = dir / "space.json";
  ::testing::internal::CaptureStdout();
  ASSERT_EQ(run_cli({"space", "fit", s.judgments.string(), "--descriptors", s.catalog.string(),
                     "--lambda", "1", "--starts", "4", "--bootstrap", "20", "--plot",
                     (dir / "space.png").string(), "-o", space_file.string()}),
            0);
  std::string out = ::testing::internal::GetCapturedStdout();
  EXPECT_TRUE(nibrig::test::is_png(dir / "space.png"));
  const auto space = model::space::read_space_file(space_file);
  ASSERT_TRUE(space.descriptor_map.has_value());
  EXPECT_EQ(space.regions.size(), 12u);
  EXPECT_EQ(space.bootstrap_resamples, 20);
  // The truth is linear in the descriptors, so the map explains almost all of each axis.
  for (double r2 : space.descriptor_map->r_squared) EXPECT_GT(r2, 0.9);

  ::testing::internal::CaptureStdout();
  ASSERT_EQ(run_cli({"space", "evaluate", space_file.string(), s.new_tool_judgments.string(),
                     "--catalog", s.catalog.string(), "-o", (dir / "scores.json").string()}),
            0);
  out = ::testing::internal::GetCapturedStdout();
  const auto scores = nibrig::test::read_json(dir / "scores.json");
  EXPECT_EQ(scores["placed_from_descriptors"], 1) << out;
  // The new tool placed from descriptors predicts most majority answers: the simulated observer
  // agrees with its own truth on ~85 % of these triplets; 70 % leaves room for the placement's
  // error and still rejects chance (50 %).
  EXPECT_GT(scores["majority_agreements"].get<double>() / scores["majority_trials"].get<double>(),
            0.7)
      << out;
  EXPECT_GT(scores["pearson_r"].get<double>(), 0.6) << out;

  ::testing::internal::CaptureStdout();
  ASSERT_EQ(run_cli({"space", "predict", space_file.string(), s.new_tool_judgments.string(),
                     "--catalog", s.catalog.string()}),
            0);
  out = ::testing::internal::GetCapturedStdout();
  EXPECT_EQ(out.substr(0, out.find('\n')), "reference,a,b,p_first,p_first_sd");
  EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), 31) << out;

  ::testing::internal::CaptureStdout();
  ASSERT_EQ(run_cli({"space", "embed", space_file.string(), s.catalog.string(), "-o",
                     (dir / "placed.csv").string(), "--plot", (dir / "placed.png").string()}),
            0);
  ::testing::internal::GetCapturedStdout();
  EXPECT_TRUE(nibrig::test::is_png(dir / "placed.png"));
  std::ifstream placed(dir / "placed.csv");
  std::string header;
  std::getline(placed, header);
  EXPECT_EQ(header, "stimulus,judged,axis1,axis1_sd,axis2,axis2_sd");
}

TEST(SpaceCliDescriptors, ValidateScansDimensionsAndLambdas) {
  const auto dir = nibrig::test::scratch_dir("cli_space_validate");
  const Study s = descriptor_study(dir);
  ::testing::internal::CaptureStdout();
  ASSERT_EQ(run_cli({"space", "validate", s.judgments.string(), "--descriptors",
                     s.catalog.string(), "--dims", "1,2", "--lambdas", "0,1", "--folds", "3",
                     "--starts", "2", "-o", (dir / "report" / "validation.json").string(),
                     "--plots", (dir / "report").string()}),
            0);
  const std::string out = ::testing::internal::GetCapturedStdout();
  const auto v = nibrig::test::read_json(dir / "report" / "validation.json");
  ASSERT_EQ(v["points"].size(), 4u) << out;
  EXPECT_TRUE(nibrig::test::is_png(dir / "report" / "dimension_scan.png"));
  // A 2-D truth: the 2-D spaces predict held-out triplets better than the 1-D ones.
  EXPECT_LT(v["points"][2]["mean_error"].get<double>(), v["points"][0]["mean_error"].get<double>());
}

TEST(SpaceCliDescriptors, DescriptorRowsThatDoNotMatchFailInOneLine) {
  const auto dir = nibrig::test::scratch_dir("cli_space_descriptors_bad");
  std::ofstream(dir / "j.csv") << "reference,a,b,count_a,count_b\ncryon/office,stab/stone,"
                                  "unicorn/office,1,0\n";
  ::testing::internal::CaptureStderr();
  EXPECT_NE(run_cli({"space", "fit", (dir / "j.csv").string(), "--descriptors",
                     (nibrig::test::assets_dir() / "default_catalog.json").string(), "--lambda", "1"}),
            0);
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(err.find("unicorn/office"), std::string::npos) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
}

}  // namespace
}  // namespace nibrig::ui::cli
