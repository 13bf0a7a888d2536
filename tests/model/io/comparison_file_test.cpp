// comparison.json written and read back: every field survives in the file's units, what does not
// exist stays null (NaN inside), and a file of another kind or with a broken field is refused
// naming the field.
#include "model/io/comparison_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

#include "tests/model/io/io_test_files.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::io {
namespace {

ComparisonFile sample() {
  ComparisonFile c;
  c.tool = "vero2";
  c.surface = "office";
  c.sample_rate_hz = 48000.0;
  c.segment_length = 4096;
  c.hop = 1024;
  c.window = "hann";
  c.band_min_hz = 6.0;
  c.band_max_hz = 500.0;
  ComparisonBin filled{0.017, 0.030, 0.022, 40, 2.5, 3.0, 6.0, std::log10(2.0)};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  ComparisonBin empty{0.030, 0.250, nan, 0, nan, nan, nan, nan};
  c.bins = {filled, empty};
  c.bins_with_rows = 1;
  c.rows = 40;
  c.rows_outside_speed_range = 3;
  c.mean_lsd_db = 2.5;
  c.mean_weighted_mean_log10_difference = std::log10(2.0);
  c.rows_analysed = 43;
  c.blocks_dropped = 2;
  return c;
}

TEST(ComparisonFile, RoundTripsWithSpeedsInMillimetresPerSecondAndNullForMissingValues) {
  const auto file = nibrig::test::scratch_dir("comparison_file") / "comparison.json";
  write_comparison_file(sample(), file);

  std::ifstream in(file);
  const auto j = nlohmann::json::parse(in);
  EXPECT_EQ(j.at("format"), "nibrig-comparison");
  // m/s × 1000 in the file; 1e-9 allows the product's rounding.
  EXPECT_NEAR(j["speed_bins"][0]["min_speed_mm_s"].get<double>(), 17.0, 1e-9);
  EXPECT_TRUE(j["speed_bins"][1]["lsd_db"].is_null()) << "an empty bin has no distance, not 0";
  EXPECT_TRUE(j["speed_bins"][1]["mean_speed_mm_s"].is_null());

  const ComparisonFile back = read_comparison_file(file);
  const ComparisonFile original = sample();
  EXPECT_EQ(back.tool, "vero2");
  EXPECT_EQ(back.surface, "office");
  EXPECT_EQ(back.segment_length, 4096u);
  EXPECT_EQ(back.hop, 1024u);
  EXPECT_EQ(back.window, "hann");
  EXPECT_EQ(back.band_max_hz, 500.0);
  ASSERT_EQ(back.bins.size(), 2u);
  // Through mm/s and back: within a few ulp of the m/s written.
  EXPECT_NEAR(back.bins[0].min_speed_m_s, 0.017, 1e-15);
  EXPECT_NEAR(back.bins[0].mean_speed_m_s, 0.022, 1e-15);
  EXPECT_EQ(back.bins[0].rows, 40u);
  EXPECT_EQ(back.bins[0].lsd_db, 2.5);
  EXPECT_EQ(back.bins[0].weighted_mean_log10_difference,
            original.bins[0].weighted_mean_log10_difference);
  EXPECT_TRUE(std::isnan(back.bins[1].lsd_db));
  EXPECT_TRUE(std::isnan(back.bins[1].mean_speed_m_s));
  EXPECT_EQ(back.rows_outside_speed_range, 3u);
  EXPECT_EQ(back.mean_lsd_db, 2.5);
  EXPECT_EQ(back.rows_analysed, 43u);
  EXPECT_EQ(back.blocks_dropped, 2u);
}

TEST(ComparisonFile, TheActuatorsFollowingRoundTripsAndIsNullWithoutOne) {
  const auto dir = nibrig::test::scratch_dir("comparison_file_actuator");
  write_comparison_file(sample(), dir / "none.json");
  std::ifstream none_in(dir / "none.json");
  EXPECT_TRUE(nlohmann::json::parse(none_in).at("actuator").is_null());
  EXPECT_FALSE(read_comparison_file(dir / "none.json").actuator.has_value());

  ComparisonFile played = sample();
  played.actuator = ComparisonActuator{1500, 0.0031, 0.0112, 256.0 / 48000.0};
  write_comparison_file(played, dir / "played.json");
  const auto back = read_comparison_file(dir / "played.json").actuator;
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->contacts, 1500u);
  // Through ms and back: within a few ulp.
  EXPECT_NEAR(back->follow_mean_s, 0.0031, 1e-15);
  EXPECT_NEAR(back->follow_max_s, 0.0112, 1e-15);
  EXPECT_NEAR(back->period_s, 256.0 / 48000.0, 1e-15);

  // A file written before the member existed reads as one without an actuator.
  std::ifstream in(dir / "played.json");
  auto old = nlohmann::json::parse(in);
  old.erase("actuator");
  nibrig::test::write_text(dir / "old.json", old.dump());
  EXPECT_FALSE(read_comparison_file(dir / "old.json").actuator.has_value());
}

TEST(ComparisonFile, RefusesOtherFormatsAndBrokenFieldsNamingThem) {
  const auto dir = nibrig::test::scratch_dir("comparison_file_bad");
  const auto file = dir / "comparison.json";
  write_comparison_file(sample(), file);
  std::ifstream in(file);
  const auto good = nlohmann::json::parse(in);
  const auto refuse = [&](nlohmann::json j, std::initializer_list<std::string_view> parts) {
    const auto bad = dir / "bad.json";
    nibrig::test::write_text(bad, j.dump());
    nibrig::test::expect_message_names(nibrig::test::format_error_of([&] { read_comparison_file(bad); }), parts);
  };
  auto j = good;
  j["format"] = "nibrig-catalog";
  refuse(j, {"bad.json", "format", "nibrig-comparison"});
  j = good;
  j["speed_bins"][1]["rows"] = -1;
  refuse(j, {"bad.json", "speed_bins[1].rows"});
  j = good;
  j["speed_bins"][0]["max_speed_mm_s"] = 10.0;
  refuse(j, {"speed_bins[0]", "min_speed_mm_s < max_speed_mm_s"});
  j = good;
  j["band_hz"] = {500.0, 6.0};
  refuse(j, {"band_hz", "min < max"});
  j = good;
  j["spectrogram"]["window"] = "kaiser";
  refuse(j, {"spectrogram.window", "kaiser"});
  j = good;
  j["actuator"] = {{"contacts", 3}, {"follow_mean_ms", "fast"}};
  refuse(j, {"bad.json", "actuator.follow_mean_ms"});
  j = good;
  j["overall"].erase("mean_lsd_db");
  refuse(j, {"overall.mean_lsd_db"});
}

}  // namespace
}  // namespace nibrig::model::io
