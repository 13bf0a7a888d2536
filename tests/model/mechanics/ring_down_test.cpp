#include "model/mechanics/ring_down.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace nibrig::model::mechanics {
namespace {

constexpr double kTwoPi = 2 * M_PI;

// Three bending-like modes of a clamped bar with the paper's damping: the first two underdamped,
// the third overdamped (ζ = λω/2 > 1 above ~255 Hz at λ = 1.25e-3 s).
modal::ModalModel three_modes(double lambda) {
  modal::ModalModel m;
  m.omega = {kTwoPi * 6.2, kTwoPi * 38.5, kTwoPi * 300.0};
  for (double w : m.omega) m.zeta.push_back(modal::rayleigh_damping_ratio(w, 0.0, lambda));
  m.input = {2.1, -1.7, 1.3};
  m.output = {1.4, 0.9, -0.6};
  return m;
}

// Closed-form acceleration of one underdamped mode released from rest at q0:
// q(t) = q0 e^{−ζωt}(cos ω_d t + ζω/ω_d sin ω_d t), q̈ = −ω² q − 2ζω q̇.
double released_mode_acceleration(double omega, double zeta, double q0, double t) {
  const double wd = omega * std::sqrt(1 - zeta * zeta), decay = std::exp(-zeta * omega * t);
  const double q = q0 * decay * (std::cos(wd * t) + zeta * omega / wd * std::sin(wd * t));
  const double qdot = -q0 * decay * omega * omega / wd * std::sin(wd * t);
  return -omega * omega * q - 2 * zeta * omega * qdot;
}

TEST(RingDown, OneModeReleaseMatchesTheClosedForm) {
  modal::ModalModel m;
  m.omega = {kTwoPi * 11.0};
  m.zeta = {0.03};
  m.input = {2.0};
  m.output = {1.5};
  const double preload = 0.05, rate = 1000.0, release = 0.1234;  // release between samples
  const auto a = simulate_release(m, preload, rate, 2000, release);
  const double q0 = preload / m.input[0];  // one mode: the tip moves b·q0 = preload
  double peak = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    const double t = static_cast<double>(k) / rate;
    const double expected = t < release ? 0.0
                                        : m.output[0] * released_mode_acceleration(
                                                            m.omega[0], m.zeta[0], q0, t - release);
    peak = std::max(peak, std::abs(expected));
    // The exact transition is evaluated to rounding: 1e-9 of the peak is far above accumulated
    // round-off over 2000 steps and far below any modelling error.
    EXPECT_NEAR(a[k], expected, 1e-9 * 1000) << "sample " << k;
  }
  EXPECT_GT(peak, 100.0);  // the check is not vacuous: the signal is hundreds of m/s²
}

TEST(RingDown, RescalingTheModulusScalesFrequenciesBySquareRoot) {
  const modal::ModalModel m = three_modes(1.25e-3);
  const modal::ModalModel scaled = rescale_modulus(m, 0.25, {0.0, 2e-3});
  for (std::size_t i = 0; i < m.size(); ++i) {
    EXPECT_DOUBLE_EQ(scaled.omega[i], 0.5 * m.omega[i]);
    EXPECT_DOUBLE_EQ(scaled.zeta[i], 2e-3 * scaled.omega[i] / 2);
    EXPECT_EQ(scaled.input[i], m.input[i]);
  }
}

TEST(RingDown, FitRecoversModulusDampingAndReleaseFromANoisyTrace) {
  // Truth: E = 0.45 GPa, λ = 1.25e-3 s (the paper's values), released at 0.3137 s, sensor gain 0.8.
  // The fit starts from a model computed at 1 GPa.
  const double reference_modulus = 1e9, true_modulus = 0.45e9, true_lambda = 1.25e-3,
               true_release = 0.3137;
  const modal::ModalModel reference = three_modes(0.0);
  const modal::ModalModel truth =
      rescale_modulus(reference, true_modulus / reference_modulus, {0.0, true_lambda});
  io::AccelerationTrace trace{2000.0, simulate_release(truth, 0.05, 2000.0, 8000, true_release)};
  double rms = 0;
  for (double a : trace.acceleration_m_s2) rms += a * a;
  rms = std::sqrt(rms / static_cast<double>(trace.acceleration_m_s2.size()));
  std::mt19937 generator(7);
  std::normal_distribution<double> noise(0.0, 0.05 * rms);  // 5 % noise: a cheap accelerometer
  for (double& a : trace.acceleration_m_s2) a = 0.8 * a + noise(generator);

  RingDownOptions options;
  options.reference_modulus = reference_modulus;
  const RingDownFit fit = fit_ring_down(reference, options, trace);
  // At this SNR over ~25 cycles of the first mode the Cramér-Rao bound on frequency is far below
  // 0.1 %, on the decay rate below 1 %: 1 % (E) and 3 % (λ) leave room without hiding a bias.
  EXPECT_NEAR(fit.youngs_modulus, true_modulus, 0.01 * true_modulus);
  EXPECT_NEAR(fit.rayleigh_stiffness, true_lambda, 0.03 * true_lambda);
  EXPECT_NEAR(fit.release_time, true_release, 1e-3);
  EXPECT_NEAR(fit.gain, 0.8, 0.02);
  // What is left is the noise: its share of the trace's energy is 0.05 / 0.8 ≈ 6 %.
  EXPECT_NEAR(fit.relative_residual, 0.05 / 0.8, 0.01);
  EXPECT_NEAR(fit.first_mode_hz, 6.2 * std::sqrt(0.45), 0.01);
  ASSERT_EQ(fit.fitted.size(), trace.acceleration_m_s2.size());
}

TEST(RingDown, BadInputIsRefused) {
  const modal::ModalModel m = three_modes(1e-3);
  EXPECT_THROW(simulate_release(modal::ModalModel{}, 0.05, 1000, 10), std::invalid_argument);
  EXPECT_THROW(simulate_release(m, 0.05, 0, 10), std::invalid_argument);
  EXPECT_THROW(simulate_release(m, 0.05, 1000, 10, -1), std::invalid_argument);
  RingDownOptions options;
  options.reference_modulus = 1e9;
  EXPECT_THAT(
      [&] {
        fit_ring_down(m, options, {1000.0, std::vector<double>(100, 0.0)});
      },
      ::testing::ThrowsMessage<std::invalid_argument>(::testing::HasSubstr("no signal")));
  options.reference_modulus = -1;
  EXPECT_THROW(fit_ring_down(m, options, {1000.0, std::vector<double>(100, 1.0)}),
               std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::model::mechanics
