// comparison.json: what a table says, in the file's units, with null where a value does not exist.
#include "rig/comparison_report.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>

#include "tests/support/test_paths.hpp"

namespace nibrig::rig {
namespace {

ComparisonTable two_bin_table() {
  ComparisonTable t;
  model::measure::SpeedBinResult filled;
  filled.min_speed_m_s = 0.017;
  filled.max_speed_m_s = 0.030;
  filled.mean_speed_m_s = 0.022;
  filled.rows = 40;
  filled.lsd_db = 2.5;
  filled.measured_weighted_mean = 3.0;
  filled.simulated_weighted_mean = 6.0;
  filled.weighted_mean_log10_difference = std::log10(2.0);
  model::measure::SpeedBinResult empty;
  empty.min_speed_m_s = 0.030;
  empty.max_speed_m_s = 0.250;
  empty.mean_speed_m_s = empty.lsd_db = empty.measured_weighted_mean =
      empty.simulated_weighted_mean = empty.weighted_mean_log10_difference =
          std::numeric_limits<double>::quiet_NaN();
  t.bins = {filled, empty};
  t.summary = model::measure::SpeedBinnedComparison::summarize(t.bins, 3);
  t.rows_analysed = 43;
  return t;
}

TEST(ComparisonReport, WritesEveryBinInMillimetresPerSecondWithNullForWhatDoesNotExist) {
  const auto dir = test::scratch_dir("comparison_report");
  const auto file = dir / "comparison.json";
  write_comparison_json(file, "vero2", "office", two_bin_table(), LiveComparisonSettings{});
  std::ifstream in(file);
  const auto j = nlohmann::json::parse(in);
  EXPECT_EQ(j.at("format"), "nibrig-comparison");
  EXPECT_EQ(j.at("version"), 1);
  EXPECT_EQ(j.at("tool"), "vero2");
  EXPECT_EQ(j.at("surface"), "office");
  ASSERT_EQ(j.at("speed_bins").size(), 2u);
  const auto& b0 = j["speed_bins"][0];
  // m/s × 1000; 1e-9 allows the product's rounding.
  EXPECT_NEAR(b0.at("min_speed_mm_s").get<double>(), 17.0, 1e-9);
  EXPECT_NEAR(b0.at("mean_speed_mm_s").get<double>(), 22.0, 1e-9);
  EXPECT_EQ(b0.at("rows"), 40);
  EXPECT_EQ(b0.at("lsd_db").get<double>(), 2.5);
  EXPECT_NEAR(b0.at("weighted_mean_log10_difference").get<double>(), std::log10(2.0), 1e-15);
  const auto& b1 = j["speed_bins"][1];
  EXPECT_TRUE(b1.at("lsd_db").is_null()) << "an empty bin has no distance, not 0";
  EXPECT_TRUE(b1.at("mean_speed_mm_s").is_null());
  EXPECT_EQ(b1.at("rows"), 0);
  EXPECT_EQ(j.at("overall").at("mean_lsd_db").get<double>(), 2.5) << "the mean of the filled bins";
  EXPECT_EQ(j.at("overall").at("rows_outside_speed_range"), 3);
  EXPECT_EQ(j.at("band_hz")[0].get<double>(), 6.0);
  EXPECT_EQ(j.at("band_hz")[1].get<double>(), 500.0);
  EXPECT_EQ(j.at("spectrogram").at("segment_length"), 4096);
  EXPECT_EQ(j.at("capture").at("rows_analysed"), 43);
}

}  // namespace
}  // namespace nibrig::rig
