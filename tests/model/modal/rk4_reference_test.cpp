// The exact integrators against an independent one: classical fourth-order Runge–Kutta on each
// mode's second-order ODE, with many sub-steps per sample, for forcing the exact integrators do
// not share code with (the force is evaluated as a function of continuous time). The RK4 error is
// estimated by Richardson extrapolation (S and 2S sub-steps: error(2S) ≈ |a_2S − a_S|/15), so the
// tolerance is the reference's own measured accuracy, not a guess.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numbers>
#include <vector>

#include "model/modal/linear_forcing_integrator.hpp"
#include "model/modal/sinusoid_step.hpp"
#include "tests/model/modal/modal_test_constants.hpp"

namespace nibrig::model::modal {
namespace {

using test::kPi;
using test::kRate;

// Modes up to 3 kHz and ζ up to 9 (the paper's λ at 2.9 kHz), so that RK4 with 64 sub-steps per
// sample is in its asymptotic regime even for the fast overdamped pole (≈ 2ζω·h/64 ≈ 0.11).
ModalModel model() {
  ModalModel m;
  m.omega = {2.0 * kPi * 70.0, 2.0 * kPi * 330.0, 2.0 * kPi * 1000.0, 2.0 * kPi * 2900.0};
  m.zeta = {0.02, 0.4, 1.0, 0.0};
  m.zeta[3] = rayleigh_damping_ratio(m.omega[3], 0.0, 1.25e-3);
  m.input = {0.8, -1.2, 0.7, 1.0};
  m.output = {1.1, 0.6, -0.9, 0.5};
  return m;
}

// Sensor acceleration Σ c_i q̈_i at every sample, RK4 with `sub` sub-steps per sample on
// q̈ = b f(t) − 2ζωq̇ − ω²q from rest at t = 0.
std::vector<double> rk4(const ModalModel& m, const std::function<double(double)>& force,
                        std::size_t samples, int sub) {
  std::vector<double> a(samples, 0.0);
  const double h = 1.0 / kRate / sub;
  for (std::size_t i = 0; i < m.size(); ++i) {
    const double w = m.omega[i], z = m.zeta[i], b = m.input[i];
    auto acc = [&](double t, double q, double v) {
      return b * force(t) - 2.0 * z * w * v - w * w * q;
    };
    double q = 0.0, v = 0.0;
    for (std::size_t n = 0; n < samples; ++n) {
      const double tn = static_cast<double>(n) / kRate;
      a[n] += m.output[i] * acc(tn, q, v);
      for (int s = 0; s < sub; ++s) {
        const double t = tn + s * h;
        const double k1q = v, k1v = acc(t, q, v);
        const double k2q = v + 0.5 * h * k1v, k2v = acc(t + 0.5 * h, q + 0.5 * h * k1q, k2q);
        const double k3q = v + 0.5 * h * k2v, k3v = acc(t + 0.5 * h, q + 0.5 * h * k2q, k3q);
        const double k4q = v + h * k3v, k4v = acc(t + h, q + h * k3q, k4q);
        q += h / 6.0 * (k1q + 2.0 * k2q + 2.0 * k3q + k4q);
        v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
      }
    }
  }
  return a;
}

// |exact − RK4(2S)| must be within 3× the Richardson estimate of RK4(2S)'s own error plus a
// rounding floor (1e-13 of the signal's peak, for ~10⁶ RK4 steps of rounding); and the estimate
// must be small (1e-7 of the peak), else the comparison would prove nothing.
void expect_matches_rk4(const std::vector<double>& exact, const ModalModel& m,
                        const std::function<double(double)>& force) {
  const std::vector<double> coarse = rk4(m, force, exact.size(), 32);
  const std::vector<double> fine = rk4(m, force, exact.size(), 64);
  double peak = 0.0;
  for (double x : fine) peak = std::max(peak, std::abs(x));
  for (std::size_t n = 0; n < exact.size(); ++n) {
    const double estimate = std::abs(fine[n] - coarse[n]) / 15.0;
    ASSERT_LT(estimate, 1e-7 * peak) << "sample " << n;
    ASSERT_NEAR(exact[n], fine[n], 3.0 * estimate + 1e-13 * peak) << "sample " << n;
  }
}

TEST(Rk4Reference, SumOfSinusoidsMatches) {
  const ModalModel m = model();
  const std::vector<Sinusoid> s = {{0.5, 73.0, 0.2}, {0.3, 329.0, -1.0}, {0.2, 498.0, 2.5}};
  auto force = [&](double t) {
    double f = 0.0;
    for (const auto& x : s) f += x.amplitude * std::sin(2.0 * kPi * x.frequency * t + x.phase);
    return f;
  };
  expect_matches_rk4(simulate_sinusoids(m, s, kRate, 2400), m, force);
}

TEST(Rk4Reference, PiecewiseLinearNoiseMatches) {
  // Broadband force (LCG noise up to Nyquist, Knuth's MMIX constants) joined linearly between
  // samples: RK4's sub-steps never straddle a sample, so the force is smooth within each.
  const ModalModel m = model();
  std::vector<double> samples(2400);
  std::uint64_t state = 7;
  for (auto& f : samples) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    f = static_cast<double>(state >> 11) * 0x1.0p-53 - 0.5;
  }
  auto force = [&](double t) {
    // The sub-step times come from n/f_s + s·h: guard the index against rounding at the ends.
    const double u = t * kRate;
    const auto n =
        std::min(static_cast<std::size_t>(std::max(0.0, std::floor(u))), samples.size() - 2);
    const double w = u - static_cast<double>(n);
    return samples[n] * (1.0 - w) + samples[n + 1] * w;
  };
  LinearForcingIntegrator integrator(m, kRate);
  std::vector<double> a(samples.size() - 1);
  integrator.process(samples.data(), a.data(), a.size());
  expect_matches_rk4(a, m, force);
}

}  // namespace
}  // namespace nibrig::model::modal
