#include "rt/fir_filter.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "tests/support/allocation_counter.hpp"

namespace nibrig::rt {
namespace {

std::vector<double> random_taps(std::size_t n, unsigned seed) {
  std::mt19937 generator(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<double> taps(n);
  for (double& t : taps) t = normal(generator);
  return taps;
}

TEST(FirFilter, TheImpulseResponseIsTheTaps) {
  const std::vector<double> taps = random_taps(37, 1);
  FirFilter filter(taps);
  std::vector<float> signal(60, 0.0f);
  signal[0] = 1.0f;
  filter.process(signal.data(), signal.size());
  for (std::size_t n = 0; n < signal.size(); ++n) {
    const double expected = n < taps.size() ? taps[n] : 0.0;
    // Each output is one tap times 1 (the other products are exact zeros), rounded to float.
    EXPECT_NEAR(signal[n], expected, 1e-7 * std::max(1.0, std::abs(expected))) << n;
  }
}

TEST(FirFilter, BlocksOfAnySizeEqualDirectConvolution) {
  // A few hundred taps, as the inverse filter has at the engine's ~4 kHz internal rate.
  const std::vector<double> taps = random_taps(300, 2);
  std::mt19937 generator(3);
  std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
  std::vector<float> input(20000);
  for (float& x : input) x = uniform(generator);

  std::vector<float> output = input;
  FirFilter filter(taps);
  std::uniform_int_distribution<std::size_t> block(0, 97);  // 0 included: an empty call is legal
  std::size_t done = 0;
  while (done < output.size()) {
    const std::size_t n = std::min(block(generator), output.size() - done);
    filter.process(output.data() + done, n);
    done += n;
  }

  double worst = 0.0;
  for (std::size_t n = 0; n < input.size(); ++n) {
    double direct = 0.0, scale = 0.0;
    for (std::size_t k = 0; k < taps.size() && k <= n; ++k) {
      direct += taps[k] * static_cast<double>(input[n - k]);
      scale += std::abs(taps[k] * static_cast<double>(input[n - k]));
    }
    // Relative to Σ|h·x|, the size the sum is built from: the output may cancel to near zero, but
    // its error (the final rounding to float, 6e-8 of the result, plus double round-off) cannot.
    worst = std::max(worst, std::abs(output[n] - direct) / scale);
  }
  EXPECT_LT(worst, 1e-6);
}

TEST(FirFilter, ResetForgetsTheHistory) {
  const std::vector<double> taps = random_taps(16, 4);
  FirFilter filter(taps);
  std::vector<float> noise(40, 0.5f);
  filter.process(noise.data(), noise.size());
  filter.reset();
  std::vector<float> impulse(20, 0.0f);
  impulse[0] = 1.0f;
  filter.process(impulse.data(), impulse.size());
  for (std::size_t n = 0; n < taps.size(); ++n) EXPECT_NEAR(impulse[n], taps[n], 1e-6) << n;
  EXPECT_EQ(impulse[17], 0.0f);  // nothing of the earlier input remains
}

TEST(FirFilter, ProcessNeverAllocates) {
  FirFilter filter(random_taps(256, 5));
  std::vector<float> block(64, 0.25f);
  const std::size_t before = nibrig::testing::allocations_on_this_thread();
  for (int i = 0; i < 100; ++i) filter.process(block.data(), block.size());
  filter.reset();
  EXPECT_EQ(nibrig::testing::allocations_on_this_thread(), before);
}

TEST(FirFilter, RejectsNoTapsAndNonFiniteTaps) {
  EXPECT_THROW(FirFilter(std::vector<double>{}), std::invalid_argument);
  EXPECT_THROW(FirFilter(std::vector<double>{1.0, std::nan("")}), std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::rt
