// The live comparison's table as comparison.json: a real comparison's table, written and read
// back, says what the table said.
#include "rig/comparison_report.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tests/support/test_paths.hpp"

namespace nibrig::rig {
namespace {

TEST(ComparisonReport, ATablesReportReadsBackAsTheTable) {
  // Simulated at twice the measured amplitude at two speeds: 6.02 dB and log10(2) in two bins.
  LiveComparisonSettings settings;
  LiveComparison live(settings, model::measure::ThresholdCurve({10.0, 1000.0}, {0.01, 0.1}, "t"));
  std::vector<float> measured(48000 * 3), simulated(measured.size()), speed(3000);
  for (std::size_t n = 0; n < measured.size(); ++n) {
    measured[n] = static_cast<float>(std::sin(0.01 * static_cast<double>(n)) +
                                     0.3 * std::sin(0.0537 * static_cast<double>(n)));
    simulated[n] = 2.0f * measured[n];  // exact in binary floating point
  }
  for (std::size_t i = 0; i < speed.size(); ++i) speed[i] = i < 1500 ? 0.02f : 0.2f;
  live.push(measured, simulated, speed);
  live.flush();
  live.finish();
  const ComparisonTable table = live.table();

  const auto file = nibrig::test::scratch_dir("comparison_report") / "comparison.json";
  model::io::write_comparison_file(comparison_report("vero2", "office", table, settings), file);
  const auto back = model::io::read_comparison_file(file);
  EXPECT_EQ(back.tool, "vero2");
  EXPECT_EQ(back.segment_length, settings.spectrogram.segment_length);
  EXPECT_EQ(back.band_min_hz, 6.0);
  ASSERT_EQ(back.bins.size(), table.bins.size());
  std::size_t filled = 0;
  for (std::size_t b = 0; b < back.bins.size(); ++b) {
    EXPECT_EQ(back.bins[b].rows, table.bins[b].rows);
    if (table.bins[b].rows == 0) {
      EXPECT_TRUE(std::isnan(back.bins[b].lsd_db)) << "an empty bin stays without a distance";
      continue;
    }
    ++filled;
    // Amplitude is linear in the signal: every band bin is 20·log10(2) dB up. 1e-9 allows the
    // transforms' rounding; JSON keeps doubles to the last digit.
    EXPECT_NEAR(back.bins[b].lsd_db, 20.0 * std::log10(2.0), 1e-9);
    EXPECT_NEAR(back.bins[b].weighted_mean_log10_difference, std::log10(2.0), 1e-12);
  }
  // Two speeds, and the few rows whose span straddles the step between them in bins between.
  EXPECT_GE(filled, 2u);
  EXPECT_EQ(back.rows, table.summary.rows);
  EXPECT_EQ(back.rows_analysed, table.rows_analysed);
  EXPECT_NEAR(back.mean_lsd_db, 20.0 * std::log10(2.0), 1e-9);
}

}  // namespace
}  // namespace nibrig::rig
