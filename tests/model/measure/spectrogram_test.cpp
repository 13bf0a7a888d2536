#include "model/measure/spectrogram.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "tests/model/measure/reference_dft.hpp"

namespace nibrig::model::measure {
namespace {

TEST(Spectrogram, GridFollowsTheSettings) {
  const double fs = 8000.0;
  std::vector<double> x(10000, 0.0);
  const SpectrogramSettings s{512, 128, Window::hann, true};
  const Spectrogram sg = compute_spectrogram(x, fs, s);
  // 1 + floor((10000 - 512) / 128) = 75 segments; 257 one-sided bins of fs/512 = 15.625 Hz.
  ASSERT_EQ(sg.times_s.size(), 75u);
  ASSERT_EQ(sg.frequencies_hz.size(), 257u);
  EXPECT_EQ(sg.amplitude.rows(), 75);
  EXPECT_EQ(sg.amplitude.cols(), 257);
  EXPECT_DOUBLE_EQ(sg.frequencies_hz[1], 15.625);
  EXPECT_DOUBLE_EQ(sg.frequencies_hz.back(), 4000.0);
  // Centres at (start + 256) / fs: scipy.signal.spectrogram's convention.
  EXPECT_DOUBLE_EQ(sg.times_s[0], 256.0 / fs);
  EXPECT_DOUBLE_EQ(sg.times_s[74], (74.0 * 128.0 + 256.0) / fs);
}

TEST(Spectrogram, SinusoidsComeBackInTheRightBinAtTheRightAmplitude) {
  const double fs = 1000.0;
  const std::size_t n = 20000;
  // Bin centres of a 1024-sample segment at 1 kHz (0.9765625 Hz apart): bins 128 and 300.
  const double f1 = 128 * fs / 1024.0, f2 = 300 * fs / 1024.0;
  std::vector<double> x(n);
  for (std::size_t t = 0; t < n; ++t) {
    const double time = static_cast<double>(t) / fs;
    x[t] = 0.8 * std::sin(2 * std::numbers::pi * f1 * time) +
           0.05 * std::cos(2 * std::numbers::pi * f2 * time + 0.3) +
           3.0;  // offset removed per segment
  }
  for (Window w : {Window::hann, Window::rectangular}) {
    const Spectrogram sg = compute_spectrogram(x, fs, {1024, 256, w, true});
    for (Eigen::Index i = 0; i < sg.amplitude.rows(); ++i) {
      // On-bin, so exact up to rounding; the weaker tone is also unaffected by the stronger one
      // (no leakage between bin centres 172 bins apart for either window).
      ASSERT_NEAR(sg.amplitude(i, 128), 0.8, 1e-9);
      ASSERT_NEAR(sg.amplitude(i, 300), 0.05, 1e-9);
      ASSERT_NEAR(sg.amplitude(i, 0), 0.0, 1e-9);
    }
  }
}

TEST(Spectrogram, EachRowIsTheDirectDftOfItsWindowedSegment) {
  const double fs = 300.0;
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<double> x(2000);
  for (double& v : x) v = noise(rng);
  const std::size_t length = 200, hop = 150;
  const Spectrogram sg = compute_spectrogram(x, fs, {length, hop, Window::hann, true});
  const Eigen::Index row = 7;
  const std::size_t start = static_cast<std::size_t>(row) * hop;
  double mean = 0.0;
  for (std::size_t t = 0; t < length; ++t) mean += x[start + t] / static_cast<double>(length);
  std::vector<double> y(length);
  double sum_w = 0.0;
  for (std::size_t t = 0; t < length; ++t) {
    y[t] = (x[start + t] - mean) * nibrig::test::hann(t, length);
    sum_w += nibrig::test::hann(t, length);
  }
  const auto X = nibrig::test::direct_dft(y);
  for (std::size_t k = 0; k < X.size(); ++k) {
    const double c = (k == 0 || k == length / 2) ? 1.0 : 2.0;
    // Direct O(N²) sum vs FFT: both round at ~1e-14 relative; 1e-11 absolute is generous.
    ASSERT_NEAR(sg.amplitude(row, static_cast<Eigen::Index>(k)), c * std::abs(X[k]) / sum_w, 1e-11);
  }
}

TEST(Spectrogram, RejectsBadSettingsAndShortSignals) {
  std::vector<double> x(100, 1.0);
  EXPECT_THROW(compute_spectrogram(x, 1000.0, {1, 1, Window::hann, true}), std::invalid_argument);
  EXPECT_THROW(compute_spectrogram(x, 1000.0, {64, 0, Window::hann, true}), std::invalid_argument);
  EXPECT_THROW(compute_spectrogram(x, 0.0, {64, 16, Window::hann, true}), std::invalid_argument);
  EXPECT_THROW(compute_spectrogram(x, NAN, {64, 16, Window::hann, true}), std::invalid_argument);
  EXPECT_THROW(compute_spectrogram(x, 1000.0, {128, 16, Window::hann, true}),
               std::invalid_argument);
  const Spectrogram one = compute_spectrogram(x, 1000.0, {100, 16, Window::hann, true});
  EXPECT_EQ(one.times_s.size(), 1u);  // exactly one segment fits
}

}  // namespace
}  // namespace nibrig::model::measure
