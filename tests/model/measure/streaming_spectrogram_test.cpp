// The streaming spectrogram must give the offline spectrogram's rows, whatever sizes the samples
// arrive in: the live waterfall and the report are then the same analysis.
#include "model/measure/streaming_spectrogram.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace nibrig::model::measure {
namespace {

std::vector<double> noisy_tones(std::size_t n, double fs, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 0.3);
  std::vector<double> x(n);
  for (std::size_t t = 0; t < n; ++t) {
    const double time = static_cast<double>(t) / fs;
    x[t] = 0.7 * std::sin(2 * M_PI * 440.0 * time) + 0.2 * std::sin(2 * M_PI * 97.3 * time) + 1.5 +
           noise(rng);
  }
  return x;
}

// Pushes x in blocks whose sizes cycle through `blocks` and collects every row.
struct Collected {
  std::vector<std::vector<double>> rows;
  std::vector<std::uint64_t> first_samples;
};
Collected stream(StreamingSpectrogram& s, const std::vector<double>& x,
                 const std::vector<std::size_t>& blocks) {
  Collected c;
  std::size_t pos = 0, k = 0;
  while (pos < x.size()) {
    const std::size_t n = std::min(blocks[k++ % blocks.size()], x.size() - pos);
    s.push(std::span<const double>(x).subspan(pos, n), [&](const SpectrogramRow& row) {
      EXPECT_EQ(row.index, c.rows.size()) << "rows arrive in order, none skipped";
      c.rows.emplace_back(row.amplitude.begin(), row.amplitude.end());
      c.first_samples.push_back(row.first_sample);
    });
    pos += n;
  }
  return c;
}

void expect_same_as_offline(const std::vector<double>& x, double fs, const SpectrogramSettings& s,
                            const std::vector<std::size_t>& blocks) {
  StreamingSpectrogram streaming(fs, s);
  const Collected c = stream(streaming, x, blocks);
  const Spectrogram offline = compute_spectrogram(x, fs, s);
  ASSERT_EQ(c.rows.size(), static_cast<std::size_t>(offline.amplitude.rows()))
      << "every complete segment, and only those, becomes a row";
  ASSERT_EQ(streaming.frequencies_hz(), offline.frequencies_hz);
  double worst = 0.0;
  for (std::size_t i = 0; i < c.rows.size(); ++i) {
    EXPECT_EQ(c.first_samples[i], i * s.hop);
    EXPECT_DOUBLE_EQ(streaming.row_time_s(i), offline.times_s[i]);
    for (std::size_t k = 0; k < c.rows[i].size(); ++k)
      worst =
          std::max(worst, std::abs(c.rows[i][k] - offline.amplitude(static_cast<Eigen::Index>(i),
                                                                    static_cast<Eigen::Index>(k))));
  }
  // The same analyzer on the same samples: any difference beyond rounding means a segment was
  // assembled from the wrong samples.
  EXPECT_LT(worst, 1e-9);
}

TEST(StreamingSpectrogram, GivesTheOfflineRowsForAnyBlockSizes) {
  const double fs = 48000.0;
  const auto x = noisy_tones(30000, fs, 1);
  const SpectrogramSettings s{1024, 256, Window::hann, true};
  expect_same_as_offline(x, fs, s, {1});
  expect_same_as_offline(x, fs, s, {64});
  expect_same_as_offline(x, fs, s, {480, 7, 1500, 3000, 1});
  expect_same_as_offline(x, fs, s, {30000});
}

TEST(StreamingSpectrogram, GivesTheOfflineRowsOfASignalLongEnoughToBeSplitOverThreads) {
  // 1 + (300000 - 1024) / 256 = 1168 segments: compute_spectrogram hands them to two threads, each
  // with its own analyzer; a row at the seam computed from the wrong run would differ here.
  const double fs = 48000.0;
  const auto x = noisy_tones(300000, fs, 7);
  expect_same_as_offline(x, fs, {1024, 256, Window::hann, true}, {480});
}

TEST(StreamingSpectrogram, GivesTheOfflineRowsForHopsLongerThanASegment) {
  const double fs = 1000.0;
  const auto x = noisy_tones(20000, fs, 2);
  // Hops of 1.5 and 3 segments leave samples no segment uses; they must be skipped, not shifted.
  expect_same_as_offline(x, fs, {256, 384, Window::rectangular, false}, {100, 33});
  expect_same_as_offline(x, fs, {256, 768, Window::hann, true}, {1000});
  expect_same_as_offline(x, fs, {300, 300, Window::hann, true}, {299, 301});
}

TEST(StreamingSpectrogram, FloatSamplesGiveTheRowsOfTheirDoubleValues) {
  const double fs = 8000.0;
  const auto x = noisy_tones(5000, fs, 3);
  std::vector<float> xf(x.begin(), x.end());
  std::vector<double> widened(xf.begin(), xf.end());
  const SpectrogramSettings s{512, 128, Window::hann, true};
  StreamingSpectrogram streaming(fs, s);
  std::vector<std::vector<double>> rows;
  streaming.push(std::span<const float>(xf), [&](const SpectrogramRow& row) {
    rows.emplace_back(row.amplitude.begin(), row.amplitude.end());
  });
  const Spectrogram offline = compute_spectrogram(widened, fs, s);
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(offline.amplitude.rows()));
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (std::size_t k = 0; k < rows[i].size(); ++k)
      ASSERT_NEAR(rows[i][k],
                  offline.amplitude(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)),
                  1e-9)
          << "a float stream is analysed as its exact double values";
}

TEST(StreamingSpectrogram, ResetStartsANewStream) {
  const double fs = 1000.0;
  const auto x = noisy_tones(3000, fs, 4);
  StreamingSpectrogram s(fs, {256, 64, Window::hann, true});
  std::size_t rows = 0;
  s.push(std::span<const double>(x).first(1000), [&](const SpectrogramRow&) { ++rows; });
  s.reset();
  EXPECT_EQ(s.rows(), 0u);
  expect_same_as_offline(x, fs, {256, 64, Window::hann, true}, {77});
  Collected c = stream(s, x, {77});
  EXPECT_EQ(c.first_samples.front(), 0u) << "after reset the first row starts at sample 0 again";
  EXPECT_EQ(c.rows.size(), 1 + (3000 - 256) / 64u);
}

TEST(StreamingSpectrogram, RefusesTheSettingsTheOfflineSpectrogramRefuses) {
  EXPECT_THROW(StreamingSpectrogram(1000.0, {1, 1, Window::hann, true}), std::invalid_argument);
  EXPECT_THROW(StreamingSpectrogram(1000.0, {64, 0, Window::hann, true}), std::invalid_argument);
  EXPECT_THROW(StreamingSpectrogram(0.0, {64, 16, Window::hann, true}), std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::model::measure
