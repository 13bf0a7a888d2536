#include "model/modal/modal_oscillator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <vector>

#include "tests/model/modal/modal_test_constants.hpp"
#include "tests/model/modal/quad_exponential.hpp"

namespace nibrig::model::modal {
namespace {

using nibrig::test::quad;
using nibrig::test::QuadMatrix;

using test::kEps;

// Reference in units of the step (h = 1, x = ωh, y = Ωh), with the balanced state (xq, q̇) so that
// every entry of the generator is O(x): [Re X, Im X, f, f'] with X' = (U + jy)X + (0,1)ᵀ f. Its
// exponential gives, from the column of f, ∫_0^1 e^{ρ(U+jy)}(0,1)ᵀ dρ (whose q is M₀), and from the
// column of f' (f(τ) = τ), ∫_0^1 e^{ρ(U+jy)}(0,1)ᵀ (1 − ρ) dρ (whose q is M₀ − M₁). At y = 0 the
// top-left block is Φ itself.
struct Reference {
  Transition phi;  // at h = 1; meaningful only for y = 0
  std::complex<double> m0, m1;
};

Reference reference(double x, double zeta, double y) {
  QuadMatrix a(6);
  const quad qx = x, qz = zeta, qy = y;
  for (int o : {0, 2}) {
    a(o, o + 1) = qx;   // d(xq)/dρ = x q̇
    a(o + 1, o) = -qx;  // dq̇/dρ = −x (xq) − 2ζx q̇
    a(o + 1, o + 1) = -quad(2) * qz * qx;
  }
  for (int k = 0; k < 2; ++k) {  // the j·y rotation between real and imaginary parts
    a(k, 2 + k) = -qy;
    a(2 + k, k) = qy;
  }
  a(1, 4) = 1;  // the force enters Re q̇
  a(4, 5) = 1;  // f' is the slope
  const QuadMatrix e = nibrig::test::quad_exp(a);
  Reference r;
  r.phi = {static_cast<double>(e(0, 0)), static_cast<double>(e(0, 1) / qx),
           static_cast<double>(e(1, 0) * qx), static_cast<double>(e(1, 1))};
  const quad m0r = e(0, 4) / qx, m0i = e(2, 4) / qx;
  r.m0 = {static_cast<double>(m0r), static_cast<double>(m0i)};
  r.m1 = {static_cast<double>(m0r - e(0, 5) / qx), static_cast<double>(m0i - e(2, 5) / qx)};
  return r;
}

std::vector<double> damping_ratios() {
  // Light, moderate, both sides of critical at several distances (the cancellation region of a
  // pole-difference formula), exactly critical, overdamped up to the paper's highest modes (ζ =
  // λω/2 with λ = 1.25e-3 is 80 near 20 kHz).
  return {0.0, 1e-3,        0.3,        0.99, 1.0 - 1e-7, 1.0 - 1e-12,
          1.0, 1.0 + 1e-12, 1.0 + 1e-7, 1.01, 3.0,        80.0};
}

std::vector<double> step_ratios(double zeta) {
  // ωh from far below the audio rate's modes to a mode that dies within the step, plus the points
  // where the implementation switches between closed forms (|μ|h = 1), from both sides.
  std::vector<double> x = {1e-4, 3e-2, 0.7, 1.9, 5.0, 40.0, 1e3, 1e5};
  if (zeta != 1.0) {
    const double boundary = 1.0 / std::sqrt(std::abs((zeta - 1.0) * (zeta + 1.0)));
    if (boundary < 1e4) {
      x.push_back(boundary * (1.0 - 1e-9));
      x.push_back(boundary * (1.0 + 1e-9));
    }
  }
  return x;
}

// ω = x/h and Ω = y/h are rounded doubles, so the phases the closed forms see are only known to
// about eps·ωh and eps·Ωh. A phase error of the mode matters only while the mode lasts: its weight
// ωh·e^{−ζωh} is at most ~1/ζ, hence the condition number max(1, Ωh, min(ωh, 1/ζ)). A closed form
// free of cancellation is accurate to a few of those units relative to the result (6 measured);
// 32 allows for the dozen roundings in each. (Subtracting the two poles' moments where the mode has
// died within the step loses ~ζωh/(2|μ|h) instead: 1800 units at ζ = 1, ωh = 1e5.)
double tolerance(double x, double zeta, double y) {
  return 32.0 * kEps * std::max({1.0, y, std::min(x, 1.0 / zeta)});
}

TEST(ModalOscillator, TransitionMatchesQuadPrecisionExponential) {
  const double h = 1.0 / 48000.0;
  for (double zeta : damping_ratios()) {
    for (double x : step_ratios(zeta)) {
      const Reference ref = reference(x, zeta, 0.0);
      const Transition t = mode_transition(x / h, zeta, h);
      // Entries compared in the balanced coordinates, where all four are on the same scale.
      const double scale = std::max({std::abs(ref.phi.dd), std::abs(ref.phi.dv) * x,
                                     std::abs(ref.phi.vd) / x, std::abs(ref.phi.vv)});
      // Relative to the entries themselves, which may have decayed by e^{−300}: e^{−ah} of the slow
      // pole a carries the rounding of a·h (eps·ah relative) and cos, sin of ω_d·h that of ω_d·h.
      const double rate = zeta <= 1.0 ? std::max(zeta, std::sqrt((1.0 - zeta) * (1.0 + zeta)))
                                      : 1.0 / (zeta + std::sqrt((zeta - 1.0) * (zeta + 1.0)));
      const double tol = 32.0 * kEps * std::max(1.0, rate * x) * scale;
      SCOPED_TRACE(::testing::Message() << "zeta " << zeta << " omega*h " << x);
      EXPECT_NEAR(t.dd, ref.phi.dd, tol);
      EXPECT_NEAR(t.dv / h * x, ref.phi.dv * x, tol);
      EXPECT_NEAR(t.vd * h / x, ref.phi.vd / x, tol);
      EXPECT_NEAR(t.vv, ref.phi.vv, tol);
    }
  }
}

TEST(ModalOscillator, MomentsMatchQuadPrecisionExponential) {
  const double h = 1.0 / 48000.0;
  for (double zeta : damping_ratios()) {
    for (double x : step_ratios(zeta)) {
      // Forcing at rest, far below, near and at the mode, and above it.
      for (double y : {0.0, 1e-3, 0.065, 0.5, x, 3.0}) {
        const Reference ref = reference(x, zeta, y);
        const double omega = x / h, big_omega = y / h;
        const std::complex<double> m0 = impulse_response_moment(omega, zeta, h, 0, big_omega);
        const std::complex<double> m1 = impulse_response_moment(omega, zeta, h, 1, big_omega);
        SCOPED_TRACE(::testing::Message()
                     << "zeta " << zeta << " omega*h " << x << " Omega*h " << y);
        // M_m(h) = h^{m+2} M_m(1) for ω = x/h, Ω = y/h (substitute r = hρ; g has units of time).
        EXPECT_LE(std::abs(m0 / (h * h) - ref.m0), tolerance(x, zeta, y) * std::abs(ref.m0));
        EXPECT_LE(std::abs(m1 / (h * h * h) - ref.m1), tolerance(x, zeta, y) * std::abs(ref.m1));
      }
    }
  }
}

TEST(ModalOscillator, NoCancellationAcrossCriticalDamping) {
  // ζ = 1 ± δ differs from ζ = 1 by O(δ) in every entry (the closed forms are smooth in ζ); a
  // formula dividing by s₁ − s₂ ∝ √(ζ²−1) would lose about eps/√δ ~ 1e-8 here instead.
  const double h = 1.0 / 48000.0;
  for (double x : {1e-3, 0.5, 20.0}) {
    const double omega = x / h;
    const Transition c = mode_transition(omega, 1.0, h);
    const std::complex<double> m0 = impulse_response_moment(omega, 1.0, h, 0);
    const std::complex<double> m1 = impulse_response_moment(omega, 1.0, h, 1);
    for (double delta : {-1e-15, -1e-13, 1e-13, 1e-15}) {
      const Transition t = mode_transition(omega, 1.0 + delta, h);
      // |∂/∂ζ| of each quantity is below ~4·max(1, ωh)² times its scale; 1e-13 · that plus
      // rounding.
      const double slope = 4.0 * std::max(1.0, x * x) * std::abs(delta) + 16.0 * kEps;
      SCOPED_TRACE(::testing::Message() << "omega*h " << x << " delta " << delta);
      EXPECT_NEAR(t.dd, c.dd, slope * std::abs(c.dd) + 1e-300);
      EXPECT_NEAR(t.dv, c.dv, slope * std::abs(c.dv));
      EXPECT_NEAR(t.vv, c.vv, slope * std::max(std::abs(c.vv), std::abs(c.dd)));
      EXPECT_NEAR(impulse_response_moment(omega, 1.0 + delta, h, 0).real(), m0.real(),
                  slope * m0.real());
      EXPECT_NEAR(impulse_response_moment(omega, 1.0 + delta, h, 1).real(), m1.real(),
                  slope * m1.real());
    }
  }
}

TEST(ModalOscillator, ModeThatDiesWithinTheStepGivesTheInfiniteIntegrals) {
  // When e^{−(slow pole)·h} underflows, ∫_0^h = ∫_0^∞ to the last bit: ∫_0^∞ g = 1/ω² (static
  // compliance) and ∫_0^∞ r g = 2ζω/ω⁴ (−d/ds of 1/(s² + 2ζωs + ω²) at 0). The slow pole of ζ = 50,
  // ωh = 1e6 is ωh/(2ζ)… ≈ 1e4 per step. Tolerance: a few roundings of each closed form.
  const double h = 1.0 / 48000.0;
  for (double zeta : {0.5, 1.0, 50.0}) {
    const double omega = 1e6 / h;
    const Transition t = mode_transition(omega, zeta, h);
    EXPECT_EQ(t.dd, 0.0);
    EXPECT_EQ(t.dv, 0.0);
    EXPECT_EQ(t.vv, 0.0);
    const double w2 = omega * omega;
    EXPECT_NEAR(impulse_response_moment(omega, zeta, h, 0).real(), 1.0 / w2, 1e-14 / w2);
    EXPECT_NEAR(impulse_response_moment(omega, zeta, h, 1).real(), 2.0 * zeta * omega / (w2 * w2),
                1e-14 * 2.0 * zeta * omega / (w2 * w2));
  }
}

TEST(ModalOscillator, UndampedModeAtExactResonanceIsFinite) {
  // ζ = 0, Ω = ω: Eq. 9's (Ω² + U²)⁻¹ is singular, but the moment is finite. With g = sin(ωr)/ω and
  // sin(ωr) = (e^{jωr} − e^{−jωr})/2j, ∫_0^h sin(ωr) e^{jωr} dr = jh/2 + (1 − e^{2jωh})/(4ω). That
  // form cancels for ωh ≪ 1 (the quad reference above covers small ωh at resonance), so ωh ≥ 0.7.
  const double h = 1.0 / 48000.0;
  const std::complex<double> j(0.0, 1.0);
  for (double x : {0.7, 2.5, 40.0}) {
    const double omega = x / h;
    const std::complex<double> expected =
        (j * h / 2.0 + (1.0 - std::exp(2.0 * j * x)) / (4.0 * omega)) / omega;
    const std::complex<double> got = impulse_response_moment(omega, 0.0, h, 0, omega);
    EXPECT_LE(std::abs(got - expected), tolerance(x, 0.0, x) * std::abs(expected))
        << "omega*h " << x;
  }
}

}  // namespace
}  // namespace nibrig::model::modal
