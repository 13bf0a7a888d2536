// A measured plan is another algorithm for the same transform: it must give the estimated plan's
// values to rounding, and a transform without a plan for a direction must refuse it.
#include "model/numeric/real_fft.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace nibrig::model::numeric {
namespace {

TEST(RealFft, AMeasuredBackwardPlanGivesTheEstimatedOnesValues) {
  const std::size_t n = 8192;  // the forcing generator's frame at the engine's 8 kHz
  RealFft estimated(n, RealFft::Plans::forward_and_backward);
  RealFft measured(n, RealFft::Plans::backward, RealFft::Planning::measured);
  std::mt19937_64 rng(11);
  std::normal_distribution<double> normal;
  for (std::size_t k = 0; k < estimated.bins(); ++k) {
    const std::complex<double> z(normal(rng),
                                 k == 0 || k + 1 == estimated.bins() ? 0 : normal(rng));
    estimated.spectrum()[k] = z;
    measured.spectrum()[k] = z;
  }
  estimated.backward();
  measured.backward();
  double peak = 0, gap = 0;
  for (std::size_t i = 0; i < n; ++i) {
    peak = std::max(peak, std::abs(estimated.real()[i]));
    gap = std::max(gap, std::abs(estimated.real()[i] - measured.real()[i]));
  }
  ASSERT_GT(peak, 0.0);
  // Two orders of summation over 13 radix stages: a few ulps of the values' size, far under 1e-12.
  EXPECT_LT(gap / peak, 1e-12);
  EXPECT_THROW(measured.forward(), std::logic_error);
  RealFft forward_only(16, RealFft::Plans::forward);
  EXPECT_THROW(forward_only.backward(), std::logic_error);
}

}  // namespace
}  // namespace nibrig::model::numeric
