// The audio thread's Gaussian draws: the array form against the one-pair form it replaces in the
// forcing generator, and both against the standard normal distribution's moments.
#include "rt/gaussian_noise.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <vector>

#include "model/numeric/vector_math.hpp"
#include "tests/support/allocation_counter.hpp"

namespace nibrig::rt {
namespace {

TEST(GaussianNoise, PairsDrawnTogetherAreTheOnePairDrawsToRounding) {
  // The same uniforms in the same order; only the log, sin and cos differ (libmvec's, within 4 ulp
  // of the scalar ones): a few 1e-16 of a value of order one, so 1e-13 leaves a wide margin, and a
  // draw out of order would miss it by far.
  model::numeric::vector_math_kind();
  GaussianNoise one(42), many(42);
  std::vector<double> first(300), second(300), scratch(300);
  std::size_t drawn = 0;
  for (std::size_t n : {1u, 7u, 64u, 300u, 0u, 129u}) {
    const std::size_t before = nibrig::testing::allocations_on_this_thread();
    many.normal_pairs(first.data(), second.data(), scratch.data(), n);
    EXPECT_EQ(nibrig::testing::allocations_on_this_thread(), before);
    for (std::size_t i = 0; i < n; ++i) {
      double a = 0.0, b = 0.0;
      one.normal_pair(a, b);
      ASSERT_NEAR(first[i], a, 1e-13 * (1.0 + std::abs(a))) << "pair " << drawn + i;
      ASSERT_NEAR(second[i], b, 1e-13 * (1.0 + std::abs(b))) << "pair " << drawn + i;
    }
    drawn += n;
  }
}

TEST(GaussianNoise, PairsDrawnTogetherHaveTheStandardNormalsMoments) {
  // 2·10⁶ values: the mean's standard error is 7·10⁻⁴ and the variance's 1·10⁻³, so five of
  // them each; the two halves of a pair are uncorrelated (standard error 1·10⁻³ for 10⁶ pairs).
  model::numeric::vector_math_kind();
  GaussianNoise noise(7);
  constexpr std::size_t kPairs = 1'000'000, kChunk = 512;
  std::vector<double> first(kChunk), second(kChunk), scratch(kChunk);
  double sum = 0.0, squares = 0.0, fourth = 0.0, cross = 0.0;
  for (std::size_t done = 0; done < kPairs; done += kChunk) {
    noise.normal_pairs(first.data(), second.data(), scratch.data(), kChunk);
    for (std::size_t i = 0; i < kChunk; ++i) {
      for (double x : {first[i], second[i]}) {
        sum += x;
        squares += x * x;
        fourth += x * x * x * x;
      }
      cross += first[i] * second[i];
    }
  }
  const double n = 2.0 * static_cast<double>(kPairs / kChunk * kChunk);
  EXPECT_NEAR(sum / n, 0.0, 5 * std::sqrt(1.0 / n));
  EXPECT_NEAR(squares / n, 1.0, 5 * std::sqrt(2.0 / n));
  // The fourth moment is 3 (its standard error √(96/n)): a Gaussian's tails, not a uniform's 1.8.
  EXPECT_NEAR(fourth / n, 3.0, 5 * std::sqrt(96.0 / n));
  EXPECT_NEAR(cross / (n / 2), 0.0, 5 * std::sqrt(2.0 / n));
}

}  // namespace
}  // namespace nibrig::rt
