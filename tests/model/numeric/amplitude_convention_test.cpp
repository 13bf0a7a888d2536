#include "model/numeric/amplitude_convention.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "model/numeric/real_fft.hpp"

namespace nibrig::model::numeric {
namespace {

TEST(AmplitudeConvention, InverseOfEachOther) {
  for (double a : {0.0, 1e-3, 0.7, 12.0})
    EXPECT_NEAR(mean_amplitude_from_noise_psd(noise_psd_from_mean_amplitude(a, 1.5), 1.5), a,
                1e-12 * (1 + a));
}

// The reference: white Gaussian noise of variance σ² at rate fs has the one-sided PSD 2σ²/fs
// (Parseval); its mean |FFT|·2/N over many rectangular 1.5 s windows must read the predicted
// amplitude in every bin.
TEST(AmplitudeConvention, WhiteNoiseReadsThePredictedMeanAmplitude) {
  const double fs = 1000.0, sigma = 0.3;
  const std::size_t n = 1500, windows = 400;
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal(0.0, sigma);
  RealFft fft(n, RealFft::Plans::forward);
  std::vector<double> mean(fft.bins(), 0.0);
  for (std::size_t w = 0; w < windows; ++w) {
    for (double& x : fft.real()) x = normal(rng);
    fft.forward();
    for (std::size_t k = 0; k < mean.size(); ++k)
      mean[k] += 2.0 * std::abs(fft.spectrum()[k]) / static_cast<double>(n) / windows;
  }
  double average = 0.0;
  for (std::size_t k = 1; k + 1 < mean.size(); ++k) average += mean[k] / (mean.size() - 2);
  const double predicted = mean_amplitude_from_noise_psd(2 * sigma * sigma / fs, 1.5);
  // 400 windows × 748 bins of Rayleigh variables (relative sd 0.52 each): the grand mean has a
  // relative sd of 0.1 %; 1 % is ten of those.
  EXPECT_NEAR(average / predicted, 1.0, 0.01);
}

}  // namespace
}  // namespace nibrig::model::numeric
