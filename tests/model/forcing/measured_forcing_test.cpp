#include "model/forcing/measured_forcing.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "model/modal/frequency_response.hpp"

namespace nibrig::model::forcing {
namespace {

// One mode, so H has a closed form to check against: H(f) = c·b·(−Ω²)/(ω² − Ω² + 2jζωΩ).
modal::ModalModel one_mode() { return {{2 * M_PI * 150}, {0.1}, {2.0}, {0.5}}; }

TEST(MeasuredForcing, DividesByTheResponseWhereItIsWellConditioned) {
  io::VelocitySpectrum a{{50, 150, 400}, {0.05, 0.1}, {{1, 2, 3}, {4, 5, 6}}};
  const auto f = forcing_from_acceleration(a, one_mode(), 0.0);
  const double w = 2 * M_PI * 150;
  for (std::size_t k = 0; k < 3; ++k) {
    const double W = 2 * M_PI * a.frequencies_hz[k];
    const double h = W * W / std::abs(std::complex<double>(w * w - W * W, 2 * 0.1 * w * W));
    for (std::size_t s = 0; s < 2; ++s)
      EXPECT_NEAR(f.amplitude_m_s2[s][k], a.amplitude_m_s2[s][k] / h, 1e-9 * f.amplitude_m_s2[s][k]);
  }
}

TEST(MeasuredForcing, RegularisationBoundsTheForceWhereTheStylusBarelyResponds) {
  // At 1 Hz the one-mode H is ~(1/150)² = 4.4e-5 of its low-frequency asymptote: dividing would
  // multiply by 2e4; with ε = 1e-3 the gain is at most 1/(2ε·max|H|).
  io::VelocitySpectrum a{{1, 150}, {0.1}, {{1, 1}}};
  const auto f = forcing_from_acceleration(a, one_mode(), 1e-3);
  const auto h = modal::frequency_response(one_mode(), a.frequencies_hz);
  const double peak = std::max(std::abs(h[0]), std::abs(h[1]));
  EXPECT_LE(f.amplitude_m_s2[0][0], 1.0 / (2 * 1e-3 * peak) * (1 + 1e-12));
  EXPECT_NEAR(f.amplitude_m_s2[0][1], 1 / std::abs(h[1]), 1e-5 / std::abs(h[1]));
  EXPECT_THROW(forcing_from_acceleration(a, one_mode(), -1), std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::model::forcing
