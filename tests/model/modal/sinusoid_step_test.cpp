#include "model/modal/sinusoid_step.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "tests/model/modal/modal_test_constants.hpp"

namespace nibrig::model::modal {
namespace {

using test::kPi;
using test::kRate;

// Closed-form steady state of q̈ + 2ζωq̇ + ω²q = A sin(Ωt + φ): q = A·Im(H e^{j(Ωt+φ)}) with
// H = 1/(ω² − Ω² + 2jζωΩ); q̇ and q̈ carry the factors jΩ and −Ω².
struct SteadyState {
  double omega, zeta, amplitude, big_omega, phase;
  std::complex<double> h() const {
    return 1.0 / std::complex<double>(omega * omega - big_omega * big_omega,
                                      2.0 * zeta * omega * big_omega);
  }
  std::complex<double> phasor(double t) const {
    return amplitude * std::polar(1.0, big_omega * t + phase);
  }
  double q(double t) const { return (h() * phasor(t)).imag(); }
  double v(double t) const {
    return (std::complex<double>(0.0, big_omega) * h() * phasor(t)).imag();
  }
  double a(double t) const { return (-big_omega * big_omega * h() * phasor(t)).imag(); }
};

// Least-squares amplitude and phase of x[n] ≈ R sin(Ωt_n + ψ) over the samples.
std::pair<double, double> fit_sinusoid(const std::vector<double>& x, double big_omega) {
  double ss = 0, sc = 0, cc = 0, xs = 0, xc = 0;
  for (std::size_t n = 0; n < x.size(); ++n) {
    const double t = static_cast<double>(n) / kRate;
    const double s = std::sin(big_omega * t), c = std::cos(big_omega * t);
    ss += s * s;
    sc += s * c;
    cc += c * c;
    xs += x[n] * s;
    xc += x[n] * c;
  }
  const double det = ss * cc - sc * sc;
  const double p = (xs * cc - xc * sc) / det;  // coefficient of sin = R cos ψ
  const double r = (xc * ss - xs * sc) / det;  // coefficient of cos = R sin ψ
  return {std::hypot(p, r), std::atan2(r, p)};
}

double wrap(double angle) { return std::remainder(angle, 2.0 * kPi); }

// Starting from the exact steady-state state makes the expected motion a pure sinusoid from the
// first step, so every sample tests Φ and the forcing gains; from rest, the transient of the
// lightest mode here (ζ = 0.02 at 300 Hz) would need ~0.7 s to fall below 1e-12. Tolerance 1e-9
// of the amplitude is the accuracy the integrator must have; rounding alone predicts ~1e-13 (each
// step adds a few ulps, the mode forgets them at rate ζω, ≤ 1/(ζωh) ≈ 1300 steps of memory).
TEST(SinusoidStep, HoldsTheClosedFormSteadyStateForEveryDampingRegime) {
  const double h = 1.0 / kRate;
  const double omega = 2.0 * kPi * 300.0;
  for (double zeta : {0.0, 0.02, 0.5, 1.0, 2.5, 40.0}) {
    for (double f : {37.0, 299.0, 300.0, 480.0}) {
      if (zeta == 0.0 && f == 300.0) continue;  // no steady state at undamped resonance
      const SteadyState ss{omega, zeta, 0.8, 2.0 * kPi * f, 0.3};
      const SinusoidStep step = make_sinusoid_step(omega, zeta, h, ss.big_omega);
      ModeState x{ss.q(0.0), ss.v(0.0)};
      const double q_amp = std::abs(ss.amplitude * ss.h());
      const double v_amp = q_amp * ss.big_omega;
      const double a_amp = v_amp * ss.big_omega;
      std::vector<double> a(4800);
      double worst_q = 0.0, worst_v = 0.0, worst_a = 0.0;
      for (std::size_t n = 0; n < a.size(); ++n) {
        const double t = static_cast<double>(n) * h;
        if (n > 0) x = step.advance(x, ss.amplitude, ss.big_omega * t + ss.phase);
        const double force = ss.amplitude * std::sin(ss.big_omega * t + ss.phase);
        a[n] = modal_acceleration(omega, zeta, x, force);
        worst_q = std::max(worst_q, std::abs(x.displacement - ss.q(t)) / q_amp);
        worst_v = std::max(worst_v, std::abs(x.velocity - ss.v(t)) / v_amp);
        worst_a = std::max(worst_a, std::abs(a[n] - ss.a(t)) / a_amp);
      }
      SCOPED_TRACE(::testing::Message() << "zeta " << zeta << " forcing " << f << " Hz");
      EXPECT_LT(worst_q, 1e-9);
      EXPECT_LT(worst_v, 1e-9);
      EXPECT_LT(worst_a, 1e-9);
      // The same as amplitude and phase of the acceleration (the quantities the paper compares).
      const auto [amplitude, phase] = fit_sinusoid(a, ss.big_omega);
      const std::complex<double> expected = -ss.big_omega * ss.big_omega * ss.amplitude * ss.h();
      EXPECT_NEAR(amplitude, std::abs(expected), 1e-9 * std::abs(expected));
      EXPECT_NEAR(wrap(phase - std::arg(expected) - ss.phase), 0.0, 1e-9);
    }
  }
}

TEST(SinusoidStep, UndampedModeAtResonanceGrowsLinearly) {
  // Where Eq. 9's (Ω² + U²)⁻¹ does not exist: from rest, q̈ + ω²q = A sin ωt has the closed form
  // q = A/(2ω²)(sin ωt − ωt cos ωt). After 1 s (300 periods) the amplitude is ~940× the static one;
  // tolerance 1e-9 of the final amplitude A·t/(2ω), for rounding accumulated without damping.
  const double h = 1.0 / kRate;
  const double omega = 2.0 * kPi * 300.0, amplitude = 1.5;
  const SinusoidStep step = make_sinusoid_step(omega, 0.0, h, omega);
  ModeState x;
  const std::size_t steps = 48000;
  const double scale = amplitude * 1.0 / (2.0 * omega);
  for (std::size_t n = 1; n <= steps; ++n) {
    const double t = static_cast<double>(n) * h;
    x = step.advance(x, amplitude, sample_phase(300.0, kRate, n));
    const double q =
        amplitude / (2.0 * omega * omega) * (std::sin(omega * t) - omega * t * std::cos(omega * t));
    ASSERT_NEAR(x.displacement, q, 1e-9 * scale) << "step " << n;
  }
}

TEST(SinusoidStep, SamplePhaseIsReducedExactlyForIntegerFrequencies) {
  // 440/48000 = 11/1200 cycles per sample: the phase repeats every 1200 samples, and sample
  // 1200k + n must have the phase of sample n to the last bit, however large k.
  for (std::size_t n : {std::size_t{0}, std::size_t{7}, std::size_t{599}}) {
    EXPECT_EQ(sample_phase(440.0, kRate, n), sample_phase(440.0, kRate, n + 1200 * 100000));
  }
  EXPECT_DOUBLE_EQ(sample_phase(12000.0, kRate, 1), kPi / 2.0);
}

}  // namespace
}  // namespace nibrig::model::modal
