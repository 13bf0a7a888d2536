// The CSV tables `space embed` and `space predict` write, written and read back: the numbers within
// the digits the writer keeps, names (quoted ones included) and flags exactly.
#include "model/space/query_csv.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "model/io/format_error.hpp"
#include "model/space/simulated_study.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::space {
namespace {

const std::filesystem::path& query_csv_catalog_file() {
  static const std::filesystem::path f = nibrig::test::assets_dir() / "default_catalog.json";
  return f;
}

const io::Catalog& query_csv_catalog() {
  static const io::Catalog c = io::read_catalog(query_csv_catalog_file());
  return c;
}

const SpaceFile& query_csv_space() {
  static const SpaceFile s = [] {
    SimulatedStudyOptions o;
    o.bootstrap_resamples = 2;  // the fewest it takes: the tables hold no bootstrap region
    return run_simulated_study(query_csv_catalog(), query_csv_catalog_file(), o).space;
  }();
  return s;
}

std::string query_csv_slurp(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(EmbedCsv, RoundTripsEveryPlacementToItsEightDigits) {
  std::vector<PlacedPairing> placed =
      place_catalog(query_csv_space(), query_csv_catalog(), query_csv_catalog_file());
  ASSERT_GT(placed.size(), 20u);
  placed.front().pairing = "pred:DM85:0.5,vero:0.5,tip=2mm/glass";  // a name CSV must quote
  const auto file = nibrig::test::scratch_dir("embed_csv") / "embed.csv";
  write_embed_csv(file, placed, 2);
  const std::string text = query_csv_slurp(file);
  EXPECT_EQ(text, embed_csv_text(placed, 2));
  EXPECT_EQ(text.substr(0, text.find('\n')), "stimulus,judged,axis1,axis1_sd,axis2,axis2_sd");
  EXPECT_NE(text.find("\n\"pred:DM85:0.5,vero:0.5,tip=2mm/glass\","), std::string::npos);

  const std::vector<EmbedRow> rows = read_embed_csv(file);
  ASSERT_EQ(rows.size(), placed.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i].stimulus, placed[i].pairing);
    EXPECT_EQ(rows[i].judged, placed[i].judged);
    ASSERT_EQ(rows[i].mean.size(), 2);
    for (Eigen::Index d = 0; d < 2; ++d) {
      // Eight significant digits: within half a unit of the eighth, 5e-8 of the value.
      const double mean = placed[i].placement.mean(d);
      const double sd = std::sqrt(placed[i].placement.covariance(d, d));
      EXPECT_NEAR(rows[i].mean(d), mean, 5e-8 * std::abs(mean) + 1e-300) << rows[i].stimulus;
      EXPECT_NEAR(rows[i].sd(d), sd, 5e-8 * sd) << rows[i].stimulus;
    }
  }
}

TEST(EmbedCsv, RefusesAnotherHeaderAndAJudgedFlagThatIsNotYesOrNo) {
  const auto dir = nibrig::test::scratch_dir("embed_csv_bad");
  {
    std::ofstream(dir / "header.csv") << "stimulus,axis1\nx,1\n";
  }
  EXPECT_THROW(read_embed_csv(dir / "header.csv"), io::FormatError);
  {
    std::ofstream(dir / "judged.csv") << "stimulus,judged,axis1,axis1_sd\na/b,maybe,1,0.5\n";
  }
  try {
    read_embed_csv(dir / "judged.csv");
    FAIL() << "read judged 'maybe'";
  } catch (const io::FormatError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("judged.csv"), std::string::npos) << m;
    EXPECT_NE(m.find("line 2"), std::string::npos) << m;
    EXPECT_NE(m.find("yes or no"), std::string::npos) << m;
  }
}

TEST(PredictionCsv, RoundTripsTheQueriesAndTheirProbabilities) {
  io::TripletSet queries;
  queries.stimuli = {"cryon/office", "a,b/\"quoted\"", "vero1/note"};
  queries.triplets = {{0, 1, 2, 0, 0, ""}, {2, 0, 1, 0, 0, ""}};
  const std::vector<QueryPrediction> p{{0.123456789012, 0.0123}, {0.75, 0.2}};
  const auto dir = nibrig::test::scratch_dir("prediction_csv");
  for (const bool with_sd : {false, true}) {
    const auto file = dir / (with_sd ? "sd.csv" : "plain.csv");
    write_prediction_csv(file, queries, p, with_sd);
    EXPECT_EQ(query_csv_slurp(file), prediction_csv_text(queries, p, with_sd));
    const std::vector<PredictionRow> rows = read_prediction_csv(file);
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows[0].reference, "cryon/office");
    EXPECT_EQ(rows[0].a, "a,b/\"quoted\"");
    EXPECT_EQ(rows[1].b, "a,b/\"quoted\"");
    // Ten significant digits: 5e-10 of the value.
    EXPECT_NEAR(rows[0].p_first, 0.123456789012, 5e-10 * 0.1234568);
    EXPECT_EQ(rows[1].p_first, 0.75);
    EXPECT_EQ(rows[0].p_first_sd.has_value(), with_sd);
    if (with_sd) EXPECT_EQ(*rows[0].p_first_sd, 0.0123);  // exact in ten digits
  }
}

}  // namespace
}  // namespace nibrig::model::space
