#include "model/measure/spectrum_analyzer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <thread>

#include "tests/model/measure/reference_dft.hpp"

namespace nibrig::model::measure {
namespace {

std::vector<double> sine(std::size_t n, double cycles_per_segment, double amplitude, double phase) {
  std::vector<double> x(n);
  for (std::size_t t = 0; t < n; ++t) {
    x[t] = amplitude * std::sin(2.0 * std::numbers::pi * cycles_per_segment *
                                    static_cast<double>(t) / static_cast<double>(n) +
                                phase);
  }
  return x;
}

TEST(WindowCoefficients, PeriodicHannMatchesSineSquaredForm) {
  const auto w = window_coefficients(Window::hann, 16);
  // 0.5 - 0.5 cos(2πn/N) = sin²(πn/N): same values by a trigonometric identity; 1e-15 is rounding.
  for (std::size_t n = 0; n < 16; ++n) EXPECT_NEAR(w[n], nibrig::test::hann(n, 16), 1e-15);
}

class OnBinSine : public ::testing::TestWithParam<Window> {};

TEST_P(OnBinSine, ReadsItsAmplitudeAtItsBin) {
  const std::size_t n = 1024;
  SpectrumAnalyzer analyzer(n, GetParam());
  std::vector<double> out(analyzer.bins());
  for (std::size_t k :
       {3u, 40u, 200u, 510u}) {  // away from DC/Nyquist, where the mirror image leaks
    const auto x = sine(n, static_cast<double>(k), 2.5, 0.7);
    analyzer.amplitude(x, out);
    // On a bin centre the coherent-gain correction is exact; 1e-12 allows FFT rounding over 1024
    // points.
    EXPECT_NEAR(out[k], 2.5, 1e-12) << "bin " << k;
    // Rectangular: all other bins are exactly zero; Hann leaks only into k±1 (half amplitude each).
    for (std::size_t j = 0; j < out.size(); ++j) {
      const std::size_t distance = j > k ? j - k : k - j;
      if (distance == 0) continue;
      const double expected = GetParam() == Window::hann && distance == 1 ? 1.25 : 0.0;
      ASSERT_NEAR(out[j], expected, 1e-12) << "bin " << j << " for a sine on " << k;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Windows, OnBinSine, ::testing::Values(Window::rectangular, Window::hann));

TEST(SpectrumAnalyzer, OffBinSineStaysWithinTheDocumentedScallopingLoss) {
  const std::size_t n = 2048;
  for (Window w : {Window::rectangular, Window::hann}) {
    SpectrumAnalyzer analyzer(n, w);
    std::vector<double> out(analyzer.bins());
    // Worst case of the main lobe: 2/π (rectangular) and 0.8488 (Hann, -1.42 dB) at half a bin.
    const double worst = w == Window::rectangular ? 2.0 / std::numbers::pi : 0.84883;
    for (double offset : {0.0, 0.1, 0.25, 0.4, 0.5}) {
      const auto x = sine(n, 300.0 + offset, 1.0, 0.3);
      analyzer.amplitude(x, out);
      const double peak = std::max(out[300], out[301]);
      // Leakage from the mirror image at -f adds at most ~1/(π·600) ≈ 5e-4 here: 2e-3 covers it.
      EXPECT_GE(peak, worst - 2e-3) << "offset " << offset;
      EXPECT_LE(peak, 1.0 + 2e-3) << "offset " << offset;
    }
    const auto half = sine(n, 300.5, 1.0, 0.3);
    analyzer.amplitude(half, out);
    EXPECT_NEAR(out[300], worst, 2e-3);  // the bound is reached at half a bin
  }
}

TEST(SpectrumAnalyzer, MatchesADirectDft) {
  const std::size_t n = 500;  // not a power of two: a different FFTW code path than 2^k
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.3, 1.0);
  std::vector<double> x(n);
  for (double& v : x) v = noise(rng);
  for (Window w : {Window::rectangular, Window::hann}) {
    SpectrumAnalyzer analyzer(n, w);
    std::vector<double> out(analyzer.bins());
    analyzer.amplitude(x, out, true);
    double mean = 0.0;
    for (double v : x) mean += v / static_cast<double>(n);
    std::vector<double> y(n);
    double sum_w = 0.0;
    for (std::size_t t = 0; t < n; ++t) {
      const double wt = w == Window::hann ? nibrig::test::hann(t, n) : 1.0;
      y[t] = (x[t] - mean) * wt;
      sum_w += wt;
    }
    const auto X = nibrig::test::direct_dft(y);
    for (std::size_t k = 0; k < out.size(); ++k) {
      const double c = (k == 0 || k == n / 2) ? 1.0 : 2.0;
      // O(N²) summation accumulates ~N·eps relative error: 1e-10 absolute on O(0.1) values.
      ASSERT_NEAR(out[k], c * std::abs(X[k]) / sum_w, 1e-10) << "bin " << k;
    }
  }
}

TEST(SpectrumAnalyzer, DcAndNyquistAreNotDoubled) {
  const std::size_t n = 64;
  SpectrumAnalyzer analyzer(n, Window::rectangular);
  std::vector<double> out(analyzer.bins());
  std::vector<double> x(n);
  for (std::size_t t = 0; t < n; ++t) x[t] = 0.75 + 0.5 * (t % 2 == 0 ? 1.0 : -1.0);
  analyzer.amplitude(x, out, false);
  EXPECT_NEAR(out[0], 0.75, 1e-14);     // a constant reads its value
  EXPECT_NEAR(out[n / 2], 0.5, 1e-14);  // cos(πt) of amplitude 0.5 reads 0.5
  analyzer.amplitude(x, out, true);
  EXPECT_NEAR(out[0], 0.0, 1e-14);  // mean removed
}

TEST(SpectrumAnalyzer, RectangularPsdSatisfiesParsevalExactly) {
  const std::size_t n = 777;  // odd: no Nyquist bin
  const double fs = 1000.0;
  SpectrumAnalyzer analyzer(n, Window::rectangular);
  std::vector<double> psd(analyzer.bins());
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(2.0, 0.7);
  std::vector<double> x(n);
  for (double& v : x) v = noise(rng);
  analyzer.power_spectral_density(x, fs, psd);
  double mean = 0.0, mean_square = 0.0, total = 0.0;
  for (double v : x) mean += v / static_cast<double>(n);
  for (double v : x) mean_square += (v - mean) * (v - mean) / static_cast<double>(n);
  for (double p : psd) total += p * fs / static_cast<double>(n);
  // Parseval holds exactly for the DFT; 1e-12 relative is rounding.
  EXPECT_NEAR(total / mean_square, 1.0, 1e-12);
}

TEST(SpectrumAnalyzer, HannPsdOfASineGivesItsMeanSquare) {
  const std::size_t n = 1024;
  SpectrumAnalyzer analyzer(n, Window::hann);
  std::vector<double> psd(analyzer.bins());
  const auto x = sine(n, 37.0, 3.0, 1.1);
  analyzer.power_spectral_density(x, 48000.0, psd);
  double total = 0.0;
  for (double p : psd) total += p * 48000.0 / static_cast<double>(n);
  // Σ(x w)²/Σw² = A²/2 exactly for an on-bin sine away from DC (cross terms cancel over the
  // period).
  EXPECT_NEAR(total, 4.5, 1e-10);
}

TEST(SpectrumAnalyzer, HannPsdMatchesTheMeanSquareOfStationaryNoiseOnAverage) {
  const std::size_t n = 1024, segments = 400;
  const double fs = 2000.0;
  SpectrumAnalyzer analyzer(n, Window::hann);
  std::vector<double> psd(analyzer.bins());
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 1.5);
  double ratio_sum = 0.0;
  std::vector<double> x(n);
  for (std::size_t s = 0; s < segments; ++s) {
    for (double& v : x) v = noise(rng);
    analyzer.power_spectral_density(x, fs, psd);
    double total = 0.0, mean = 0.0, ms = 0.0;
    for (double p : psd) total += p * fs / static_cast<double>(n);
    for (double v : x) mean += v / static_cast<double>(n);
    for (double v : x) ms += (v - mean) * (v - mean) / static_cast<double>(n);
    ratio_sum += total / ms;
  }
  // Per segment the ratio scatters by ~2 % (the Hann-weighted mean square uses about half the
  // samples effectively); averaged over 400 segments the SD is ~0.1 %: 0.6 % is 6 SD.
  EXPECT_NEAR(ratio_sum / segments, 1.0, 6e-3);
}

TEST(SpectrumAnalyzer, IsMovableAndChecksSizes) {
  SpectrumAnalyzer a(256, Window::hann);
  SpectrumAnalyzer b = std::move(a);
  EXPECT_EQ(b.segment_length(), 256u);
  EXPECT_EQ(b.bins(), 129u);
  EXPECT_DOUBLE_EQ(b.bin_frequency_hz(10, 1024.0), 40.0);
  std::vector<double> out(b.bins());
  const auto x = sine(256, 8.0, 1.0, 0.0);
  b.amplitude(x, out);
  EXPECT_NEAR(out[8], 1.0, 1e-12);
  std::vector<double> wrong(10);
  EXPECT_THROW(b.amplitude(wrong, out), std::invalid_argument);
  std::vector<double> small_out(5);
  EXPECT_THROW(b.amplitude(x, small_out), std::invalid_argument);
  EXPECT_THROW(b.power_spectral_density(x, 0.0, out), std::invalid_argument);
  EXPECT_THROW(SpectrumAnalyzer(1, Window::hann), std::invalid_argument);
}

TEST(SpectrumAnalyzer, PlansAreSafeToMakeFromManyThreads) {
  // FFTW's planner is not thread-safe: without the shared lock this races (and ASan/TSan builds
  // report it). Every thread must also get the single-threaded answer.
  const auto x = sine(384, 12.0, 1.0, 0.2);
  std::vector<std::thread> threads;
  std::vector<double> results(8, 0.0);
  for (std::size_t i = 0; i < results.size(); ++i) {
    threads.emplace_back([&, i] {
      for (int r = 0; r < 30; ++r) {
        SpectrumAnalyzer analyzer(384, i % 2 == 0 ? Window::hann : Window::rectangular);
        std::vector<double> out(analyzer.bins());
        analyzer.amplitude(x, out);
        results[i] = out[12];
      }
    });
  }
  for (auto& t : threads) t.join();
  for (double r : results) EXPECT_NEAR(r, 1.0, 1e-12);
}

}  // namespace
}  // namespace nibrig::model::measure
