// The frame interpolator against the band-limited signal it samples: a sum of sinusoids on the
// frame's bins, evaluated exactly at every full-rate instant.
#include "rt/frame_interpolator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace nibrig::rt {
namespace {

// A periodic signal of random bins below `active`, at instant t of an n-sample period.
struct BandLimited {
  std::vector<double> amplitude, phase;
  double at(double t, std::size_t n) const {
    double x = 0;
    for (std::size_t k = 1; k < amplitude.size(); ++k)
      x += amplitude[k] *
           std::cos(2 * std::numbers::pi * static_cast<double>(k) * t / static_cast<double>(n) +
                    phase[k]);
    return x;
  }
};

BandLimited random_band(std::size_t active, unsigned seed) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  BandLimited b;
  for (std::size_t k = 0; k < active; ++k) {
    b.amplitude.push_back(unit(generator));
    b.phase.push_back(2 * std::numbers::pi * unit(generator));
  }
  return b;
}

TEST(FrameInterpolator, ChoosesTheLargestFactorThatKeepsTheImageABandAway) {
  EXPECT_EQ(FrameInterpolator(8192, 511).factor(), 4u);  // 498 Hz at 8 kHz
  EXPECT_EQ(FrameInterpolator(4096, 511).factor(), 2u);  // 498 Hz at 4 kHz
  EXPECT_EQ(FrameInterpolator(8192, 300).factor(), 8u);
  EXPECT_EQ(FrameInterpolator(1024, 400).factor(), 1u);  // a band above a sixth of the rate
  EXPECT_EQ(FrameInterpolator(8190, 511).factor(), 2u);  // a factor must divide the frame
  EXPECT_EQ(FrameInterpolator(8192, 300, FrameRate::full).factor(), 1u);  // the reference
}

TEST(FrameInterpolator, ReproducesTheBandLimitedSignalTo80DbAndItsSamplesExactly) {
  for (std::size_t n : {4096u, 8192u}) {
    const std::size_t active = n / 16;  // 500 Hz at 8 kHz for n = 8192
    FrameInterpolator interpolator(n, active);
    const std::size_t factor = interpolator.factor();
    ASSERT_GT(factor, 1u);
    const auto band = random_band(active, static_cast<unsigned>(n));
    std::vector<double> reduced(interpolator.reduced_length()), out(n);
    for (std::size_t m = 0; m < reduced.size(); ++m)
      reduced[m] = band.at(static_cast<double>(m * factor), n);
    interpolator.interpolate(reduced.data(), out.data());
    double error = 0, power = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double want = band.at(static_cast<double>(i), n);
      error += (out[i] - want) * (out[i] - want);
      power += want * want;
      if (i % factor == 0) ASSERT_EQ(out[i], reduced[i / factor]) << i;  // phase 0 is the sample
    }
    // Designed for 80 dB of stop band: the error's RMS within 1e-4 of the signal's (the ends too,
    // since the frame wraps around).
    EXPECT_LT(std::sqrt(error / power), 1e-4) << n;
  }
}

}  // namespace
}  // namespace nibrig::rt
