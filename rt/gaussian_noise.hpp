// Gaussian random numbers for the audio thread: xoshiro256** (period 2^256 − 1, so a generated
// texture never repeats in any session) and the Box-Muller transform. No allocation, lock or
// exception; the same seed gives the same stream on every run, which offline renders rely on.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>

#include "model/numeric/vector_math.hpp"

namespace nibrig::rt {

class GaussianNoise {
 public:
  explicit GaussianNoise(std::uint64_t seed) noexcept {
    // splitmix64 spreads any seed (0 too) over the 256-bit state, as xoshiro's authors advise.
    for (auto& word : state_) {
      seed += 0x9e3779b97f4a7c15ULL;
      std::uint64_t z = seed;
      z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
      z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
      word = z ^ (z >> 31);
    }
  }

  // Uniform on (0, 1]: never 0, so log() below is finite.
  double uniform() noexcept { return (static_cast<double>(next() >> 11) + 1.0) * 0x1.0p-53; }

  // Two independent standard normal numbers.
  void normal_pair(double& first, double& second) noexcept {
    const double radius = std::sqrt(-2.0 * std::log(uniform()));
    const double angle = 2.0 * std::numbers::pi * uniform();
    first = radius * std::cos(angle);
    second = radius * std::sin(angle);
  }

  // n such pairs at once, from the same uniforms in the same order, with the log, sin and cos of a
  // whole array (model/numeric/vector_math.hpp: within 4 ulp of the scalar ones, so not bit for bit
  // normal_pair's). `scratch` holds n values. Call model::numeric::vector_math_kind() once before,
  // off the audio thread.
  void normal_pairs(double* first, double* second, double* scratch, std::size_t n) noexcept {
    for (std::size_t i = 0; i < n; ++i) {
      first[i] = uniform();
      scratch[i] = 2.0 * std::numbers::pi * uniform();
    }
    model::numeric::log_all(first, first, n);
    for (std::size_t i = 0; i < n; ++i) first[i] = std::sqrt(-2.0 * first[i]);
    model::numeric::sin_all(scratch, second, n);
    model::numeric::cos_all(scratch, scratch, n);
    for (std::size_t i = 0; i < n; ++i) {
      second[i] *= first[i];
      first[i] *= scratch[i];
    }
  }

 private:
  static std::uint64_t rotl(std::uint64_t x, int k) noexcept { return (x << k) | (x >> (64 - k)); }
  std::uint64_t next() noexcept {
    const std::uint64_t result = rotl(state_[1] * 5, 7) * 9;
    const std::uint64_t t = state_[1] << 17;
    state_[2] ^= state_[0];
    state_[3] ^= state_[1];
    state_[1] ^= state_[2];
    state_[0] ^= state_[3];
    state_[2] ^= t;
    state_[3] = rotl(state_[3], 45);
    return result;
  }

  std::uint64_t state_[4];
};

}  // namespace nibrig::rt
