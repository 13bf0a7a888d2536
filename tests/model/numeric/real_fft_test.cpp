// A transform made with one direction's plan computes what one with both computes, to the bit
// (the same FFTW_ESTIMATE plan), and refuses the direction it has no plan for.
#include "model/numeric/real_fft.hpp"

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

namespace nibrig::model::numeric {
namespace {

TEST(RealFft, ABackwardOnlyTransformIsTheFullOnesBackwardToTheBit) {
  const std::size_t n = 8192;  // the forcing generator's frame at the engine's 8 kHz
  RealFft both(n, RealFft::Plans::forward_and_backward);
  RealFft backward(n, RealFft::Plans::backward);
  std::mt19937_64 rng(11);
  std::normal_distribution<double> normal;
  for (std::size_t k = 0; k < both.bins(); ++k) {
    const std::complex<double> z(normal(rng), k == 0 || k + 1 == both.bins() ? 0 : normal(rng));
    both.spectrum()[k] = z;
    backward.spectrum()[k] = z;
  }
  both.backward();
  backward.backward();
  for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(both.real()[i], backward.real()[i]) << i;
  EXPECT_THROW(backward.forward(), std::logic_error);
  RealFft forward_only(16, RealFft::Plans::forward);
  EXPECT_THROW(forward_only.backward(), std::logic_error);
}

}  // namespace
}  // namespace nibrig::model::numeric
