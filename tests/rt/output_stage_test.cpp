#include "rt/output_stage.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "tests/support/allocation_counter.hpp"

namespace nibrig::rt {
namespace {

constexpr double kOutputRate = 48000.0;

std::vector<float> sine(double frequency, double amplitude, std::size_t n) {
  std::vector<float> s(n);
  for (std::size_t i = 0; i < n; ++i)
    s[i] = static_cast<float>(amplitude * std::sin(2 * std::numbers::pi * frequency * i / kOutputRate));
  return s;
}

float peak(const std::vector<float>& s, std::size_t from) {
  float p = 0;
  for (std::size_t i = from; i < s.size(); ++i) p = std::max(p, std::abs(s[i]));
  return p;
}

TEST(OutputStage, ASineInTheBandPassesWithTheHighPassesExactGain) {
  OutputStage stage({});
  std::vector<float> s = sine(200.0, 0.5, 48000);
  stage.process(s.data(), s.size());
  // |H(e^jω)| of y[n] = x[n] − x[n−1] + R·y[n−1] at 200 Hz, after the 5 Hz transient has decayed.
  const std::complex<double> z = std::polar(1.0, -2 * std::numbers::pi * 200.0 / kOutputRate);
  const double gain = std::abs((1.0 - z) / (1.0 - stage.dc_pole() * z));
  EXPECT_NEAR(peak(s, 24000), 0.5 * gain, 2e-4);  // float samples; the sampled peak is within 2e-5
  EXPECT_GT(gain, 0.999);  // 200 Hz is far above the corner
  EXPECT_EQ(stage.counts().limited_samples, 0u);
}

TEST(OutputStage, ADcStepDecaysWithThePole) {
  OutputStage stage({});
  std::vector<float> s(2000, 0.5f);
  stage.process(s.data(), s.size());
  // The step response of the high-pass is 0.5·R^n exactly.
  for (std::size_t n : {0u, 100u, 1999u})
    EXPECT_NEAR(s[n], 0.5 * std::pow(stage.dc_pole(), static_cast<double>(n)), 1e-6) << n;
}

TEST(OutputStage, NothingAVoiceCanComputePassesTheLimit) {
  OutputStageSettings settings;
  settings.limit = 0.7;
  OutputStage stage(settings);
  const float inf = std::numeric_limits<float>::infinity();
  std::vector<float> faults{std::nanf(""), inf, -inf, 1e30f, -1e30f, std::numeric_limits<float>::max(),
                            -std::numeric_limits<float>::max(), 3.0f, -3.0f, 0.0f};
  std::mt19937 generator(5);
  std::uniform_int_distribution<std::size_t> pick(0, faults.size() - 1);
  std::normal_distribution<float> huge(0.0f, 1e6f);
  std::vector<float> s(200000);
  for (std::size_t i = 0; i < s.size(); ++i) s[i] = i % 3 ? huge(generator) : faults[pick(generator)];
  const std::size_t before = nibrig::testing::allocations_on_this_thread();
  stage.process(s.data(), s.size());
  EXPECT_EQ(nibrig::testing::allocations_on_this_thread(), before);
  for (float x : s) {
    ASSERT_TRUE(std::isfinite(x));
    ASSERT_LE(std::abs(x), 0.7f);
  }
  EXPECT_GT(stage.counts().non_finite_samples, 0u);
  EXPECT_LE(stage.counts().peak, 0.7);
  // And it recovers: a quiet sine afterwards comes through at its own level once the gain released
  // (0.05 s time constant; 0.5 s is ten of them).
  std::vector<float> after = sine(200.0, 0.3, 48000);
  stage.process(after.data(), after.size());
  EXPECT_NEAR(peak(after, 24000), 0.3, 0.01);
}

// The high-pass runs four samples a step (a shorter serial chain); it must still be the recursion
// y[n] = x[n] − x[n−1] + R·y[n−1], whatever the chunk and block boundaries.
TEST(OutputStage, TheHighPassIsItsRecursionInAnyBlocks) {
  std::mt19937 generator(11);
  std::normal_distribution<float> noise(0.0f, 0.1f);
  std::vector<float> in(20000);
  for (std::size_t i = 0; i < in.size(); ++i)
    in[i] = noise(generator) + (i < 10000 ? 0.2f : 0.0f);  // a DC step, never near the limit
  OutputStage stage({});
  std::vector<float> out = in;
  for (std::size_t at = 0, block = 1; at < out.size(); at += block, block = block % 97 + 3)
    stage.process(out.data() + at, std::min(block, out.size() - at));
  double previous_in = 0, previous_out = 0;
  for (std::size_t i = 0; i < in.size(); ++i) {
    const double y = in[i] - previous_in + stage.dc_pole() * previous_out;
    previous_in = in[i];
    previous_out = y;
    // The two orders of the same sums differ by a few double roundings (~1e-16), far below the
    // float output's half-step (3e-8 at these levels): at most one float step apart.
    ASSERT_NEAR(out[i], y, std::abs(y) * 1.2e-7 + 1e-12) << i;
  }
  EXPECT_EQ(stage.counts().limited_samples, 0u);
}

// After a limited burst the gain releases to exactly 1, not to a rounding step below it, so quiet
// audio afterwards passes the limiter untouched.
TEST(OutputStage, TheGainReleasesToExactlyOne) {
  OutputStage stage({});
  std::vector<float> loud = sine(100.0, 2.0, 4800);
  stage.process(loud.data(), loud.size());
  EXPECT_LT(stage.gain(), 0.5);
  // From 0.45 to within 1e-12 of 1 takes ln(1e12 / 0.55) ≈ 27 time constants of 0.05 s: 1.4 s.
  std::vector<float> quiet = sine(200.0, 0.3, 96000);
  stage.process(quiet.data(), quiet.size());
  EXPECT_EQ(stage.gain(), 1.0);
}

TEST(OutputStage, ALoudSineIsHeldAtTheLimit) {
  OutputStage stage({});
  std::vector<float> s = sine(100.0, 2.0, 48000);
  stage.process(s.data(), s.size());
  EXPECT_LE(peak(s, 0), 0.9f);
  EXPECT_GT(peak(s, 24000), 0.89f);  // instant attack: the peaks sit at the limit, not below it
  EXPECT_GT(stage.counts().limited_samples, 0u);
  EXPECT_THROW(OutputStage(OutputStageSettings{48000.0, 30000.0, 0.9, 0.05}), std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::rt
