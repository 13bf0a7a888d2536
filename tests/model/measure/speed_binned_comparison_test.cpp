// The per-speed comparison of measured and simulated spectra, checked against hand computations:
// known amplitude ratios give known dB distances and descriptor differences, identical streams give
// zero, and rows land in the bin of their speed.
#include "model/measure/speed_binned_comparison.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "model/measure/streaming_spectrogram.hpp"

namespace nibrig::model::measure {
namespace {

// A threshold that is not flat, so that a weighted mean that ignored it would be caught.
ThresholdCurve test_threshold() {
  return ThresholdCurve({10.0, 100.0, 1000.0}, {0.05, 0.01, 0.2}, "test curve");
}

// 0, 10, ..., 990 Hz: the band [6, 500) holds 10, 20, ..., 490 Hz, 49 bins.
std::vector<double> frequencies() {
  std::vector<double> f(100);
  for (std::size_t k = 0; k < f.size(); ++k) f[k] = 10.0 * static_cast<double>(k);
  return f;
}

TEST(GeometricSpeedEdges, SpanTheRangeWithAConstantRatio) {
  const auto e = geometric_speed_edges(0.017, 0.250, 12);
  ASSERT_EQ(e.size(), 13u);
  EXPECT_EQ(e.front(), 0.017);
  EXPECT_EQ(e.back(), 0.250);
  const double ratio = std::pow(0.250 / 0.017, 1.0 / 12.0);
  for (std::size_t b = 1; b < e.size(); ++b)
    EXPECT_NEAR(e[b] / e[b - 1], ratio, 1e-12) << "geometric spacing, bin " << b;
  EXPECT_THROW(geometric_speed_edges(0.0, 0.25, 12), std::invalid_argument);
  EXPECT_THROW(geometric_speed_edges(0.02, 0.01, 12), std::invalid_argument);
  EXPECT_THROW(geometric_speed_edges(0.01, 0.02, 0), std::invalid_argument);
}

TEST(SpeedBinnedComparison, TheBandIsTheCatalogsHalfOpenOne) {
  SpeedBinnedComparison c(frequencies(), {}, test_threshold());
  EXPECT_EQ(c.band_first(), 1u);  // 10 Hz, the first >= 6 Hz
  EXPECT_EQ(c.band_last(), 50u);  // 500 Hz itself is out
  // 1024-sample segments at 48 kHz are 46.9 Hz apart: ten bins in the band, accepted; a band of
  // 6-40 Hz holds none and is refused rather than compared on nothing.
  std::vector<double> coarse(513);
  for (std::size_t k = 0; k < coarse.size(); ++k) coarse[k] = 46.875 * static_cast<double>(k);
  EXPECT_NO_THROW(SpeedBinnedComparison(coarse, {}, test_threshold()));
  SpeedBinnedComparisonSettings narrow;
  narrow.max_frequency_hz = 40.0;
  EXPECT_THROW(SpeedBinnedComparison(coarse, narrow, test_threshold()), std::invalid_argument);
}

TEST(SpeedBinnedComparison, RowsLandInTheBinOfTheirSpeed) {
  SpeedBinnedComparison c(frequencies(), {}, test_threshold());
  const auto& e = c.speed_edges_m_s();
  EXPECT_EQ(c.bin_of(0.017), 0u);
  EXPECT_EQ(c.bin_of(0.250), 11u) << "the last bin is closed";
  EXPECT_EQ(c.bin_of(e[5]), 5u) << "an inner edge opens its bin";
  EXPECT_EQ(c.bin_of(0.5 * (e[3] + e[4])), 3u);
  EXPECT_EQ(c.bin_of(0.0169), 12u);
  EXPECT_EQ(c.bin_of(0.2501), 12u);
  EXPECT_EQ(c.bin_of(std::nan("")), 12u);

  const std::vector<double> row(100, 1.0);
  EXPECT_TRUE(c.add(0.5 * (e[3] + e[4]), row, row));
  EXPECT_TRUE(c.add(e[3], row, row));
  EXPECT_FALSE(c.add(0.3, row, row));
  const auto r = c.results();
  EXPECT_EQ(r[3].rows, 2u);
  EXPECT_NEAR(r[3].mean_speed_m_s, 0.5 * (0.5 * (e[3] + e[4]) + e[3]), 1e-15);
  EXPECT_EQ(c.rows_outside_speed_range(), 1u);
  EXPECT_TRUE(std::isnan(r[0].lsd_db)) << "an empty bin has no distance, not a distance of 0";
  const auto s = c.summary();
  EXPECT_EQ(s.bins_with_rows, 1u);
  EXPECT_EQ(s.rows, 2u);
  EXPECT_EQ(s.rows_outside_speed_range, 1u);
  EXPECT_THROW(c.add(0.1, std::vector<double>(99, 1.0), row), std::invalid_argument);
}

TEST(SpeedBinnedComparison, IdenticalRowsAreZeroApart) {
  SpeedBinnedComparison c(frequencies(), {}, test_threshold());
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.01, 1.0);
  for (int i = 0; i < 20; ++i) {
    std::vector<double> row(100);
    for (double& v : row) v = u(rng);
    c.add(0.02 + 0.01 * i, row, row);
  }
  for (const auto& r : c.results()) {
    if (r.rows == 0) continue;
    EXPECT_EQ(r.lsd_db, 0.0);
    EXPECT_EQ(r.weighted_mean_log10_difference, 0.0);
    EXPECT_EQ(r.measured_mean, r.simulated_mean);
  }
  EXPECT_EQ(c.summary().mean_lsd_db, 0.0);
}

TEST(SpeedBinnedComparison, OneBinTwiceAsLoudGivesItsShareOfSixDecibels) {
  SpeedBinnedComparison c(frequencies(), {}, test_threshold());
  std::vector<double> measured(100, 0.1), simulated(100, 0.1);
  simulated[30] = 0.2;  // 300 Hz, inside the band
  simulated[70] = 5.0;  // 700 Hz, outside: must not count
  c.add(0.1, measured, simulated);
  const auto r = c.result(c.bin_of(0.1));
  // One of 49 band bins off by 20·log10(2) dB: RMS = 20·log10(2)/√49.
  EXPECT_NEAR(r.lsd_db, 20.0 * std::log10(2.0) / 7.0, 1e-12);
  // Weighted mean = mean over the band of a/threshold(f); only 300 Hz's term doubles.
  const ThresholdCurve t = test_threshold();
  double m = 0.0, s = 0.0;
  for (std::size_t k = 1; k < 50; ++k) {
    const double f = 10.0 * static_cast<double>(k);
    m += measured[k] / t.threshold_m_s2(f);
    s += simulated[k] / t.threshold_m_s2(f);
  }
  EXPECT_NEAR(r.measured_weighted_mean, m / 49.0, 1e-12);
  EXPECT_NEAR(r.weighted_mean_log10_difference, std::log10(s / m), 1e-12);
}

TEST(SpeedBinnedComparison, StreamsOfKnownAmplitudeRatioGiveTheKnownDistance) {
  // Measured: two sinusoids and noise; simulated: the same signal at half the amplitude. Amplitude
  // spectra are linear in the signal, so every bin is 6.02 dB down and the descriptor log10(0.5).
  const double fs = 4000.0;
  const SpectrogramSettings settings{800, 200, Window::hann, true};  // 5 Hz bins
  StreamingSpectrogram measured(fs, settings), simulated(fs, settings);
  std::mt19937 rng(6);
  std::normal_distribution<double> noise(0.0, 0.05);
  std::vector<double> x(40000), y(40000);
  for (std::size_t n = 0; n < x.size(); ++n) {
    const double t = static_cast<double>(n) / fs;
    x[n] = 0.8 * std::sin(2 * M_PI * 120.0 * t) + 0.3 * std::sin(2 * M_PI * 333.0 * t) + noise(rng);
    y[n] = 0.5 * x[n];
  }
  SpeedBinnedComparison c(measured.frequencies_hz(), {}, test_threshold());
  std::vector<std::vector<double>> rows;
  measured.push(std::span<const double>(x), [&](const SpectrogramRow& r) {
    rows.emplace_back(r.amplitude.begin(), r.amplitude.end());
  });
  std::size_t i = 0;
  simulated.push(std::span<const double>(y), [&](const SpectrogramRow& r) {
    // Two speeds, so that two bins fill.
    c.add(i < rows.size() / 2 ? 0.03 : 0.2, rows[i], r.amplitude);
    ++i;
  });
  ASSERT_EQ(i, rows.size());
  const auto s = c.summary();
  EXPECT_EQ(s.bins_with_rows, 2u);
  // Tolerance: rounding in the transforms of two separately scaled signals, far below 1e-9 dB.
  EXPECT_NEAR(s.mean_lsd_db, 20.0 * std::log10(2.0), 1e-9);
  EXPECT_NEAR(s.mean_weighted_mean_log10_difference, std::log10(0.5), 1e-12);
}

TEST(LogSpectralDistance, SkipsBinsWhereEitherIsZero) {
  const std::vector<double> m{1.0, 0.0, 1.0, 1.0}, s{10.0, 3.0, 0.0, 1.0};
  // Bins 0 and 3 count: 20 dB and 0 dB, RMS √(400/2).
  EXPECT_NEAR(log_spectral_distance_db(m, s), std::sqrt(200.0), 1e-12);
  EXPECT_TRUE(
      std::isnan(log_spectral_distance_db(std::vector<double>{0.0}, std::vector<double>{1.0})));
}

}  // namespace
}  // namespace nibrig::model::measure

namespace nibrig::model::measure {
namespace {

TEST(SpeedSamplesOfSpan, TakeTheSpeedSamplesInsideTheRowsSpan) {
  // 48 kHz against 1 kHz: 48 acceleration samples per speed sample. Samples [96, 96 + 4096) span
  // 2 ms to 87.33 ms: speed samples 2..87.
  auto r = speed_samples_of_span(96, 4096, 48000.0, 1000.0);
  EXPECT_EQ(r.begin, 2u);
  EXPECT_EQ(r.end, 88u);
  // Starting between speed samples: [100, 100 + 1024) is 2.083 ms to 23.42 ms, samples 3..23.
  r = speed_samples_of_span(100, 1024, 48000.0, 1000.0);
  EXPECT_EQ(r.begin, 3u);
  EXPECT_EQ(r.end, 24u);
  // Shorter than a speed period and holding none: the next sample.
  r = speed_samples_of_span(1, 16, 48000.0, 1000.0);
  EXPECT_EQ(r.begin, 1u);
  EXPECT_EQ(r.end, 2u);
}

}  // namespace
}  // namespace nibrig::model::measure
