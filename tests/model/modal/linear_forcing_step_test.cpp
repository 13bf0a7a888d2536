#include "model/modal/linear_forcing_step.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "tests/model/modal/modal_test_constants.hpp"
#include "tests/model/modal/quad_exponential.hpp"

namespace nibrig::model::modal {
namespace {

using nibrig::test::quad;
using nibrig::test::QuadMatrix;

using test::kEps;

// The textbook way to get Γ₀, Γ₁: the exponential of the augmented generator of [q, q̇, f, f'] (the
// force a state with constant slope), in quadruple precision and in units of the step (h = 1,
// x = ωh), with the balanced displacement xq. From rest, the column of f (f ≡ 1) is Γ₀ + Γ₁ and the
// column of f' (f(τ) = τ, rising 0 → 1) is Γ₁.
LinearForcingStep reference(double x, double zeta) {
  QuadMatrix a(4);
  const quad qx = x;
  a(0, 1) = qx;
  a(1, 0) = -qx;
  a(1, 1) = -quad(2) * quad(zeta) * qx;
  a(1, 2) = 1;
  a(2, 3) = 1;
  const QuadMatrix e = nibrig::test::quad_exp(a);
  LinearForcingStep s;
  s.transition = {static_cast<double>(e(0, 0)), static_cast<double>(e(0, 1) / qx),
                  static_cast<double>(e(1, 0) * qx), static_cast<double>(e(1, 1))};
  s.from_end = {static_cast<double>(e(0, 3) / qx), static_cast<double>(e(1, 3))};
  s.from_start = {static_cast<double>((e(0, 2) - e(0, 3)) / qx),
                  static_cast<double>(e(1, 2) - e(1, 3))};
  return s;
}

TEST(LinearForcingStep, MatchesAugmentedExponentialInQuadPrecision) {
  const double h = 1.0 / 48000.0;
  for (double zeta : {0.0, 0.01, 0.7, 1.0 - 1e-9, 1.0, 1.0 + 1e-9, 1.3, 10.0, 80.0}) {
    for (double x : {1e-4, 1e-2, 0.13, 1.0, 3.0, 30.0, 500.0}) {
      const LinearForcingStep got = make_linear_forcing_step(x / h, zeta, h);
      const LinearForcingStep ref = reference(x, zeta);
      // Γ's displacement is h² × (the unit-step value), its velocity h ×. Errors are measured in
      // the energy norm |(ωq, q̇)|, the norm in which the recursion carries them on (the free mode's
      // energy never grows, so an error made in one step is never amplified by later ones). A phase
      // or decay exponent rounded by eps·ωh moves a live mode's result by that much relative to it:
      // tolerance 32·eps·max(1, min(ωh, 1/ζ)) of the vector's norm (see modal_oscillator_test).
      const double cond = std::max(1.0, std::min(x, 1.0 / zeta));
      for (auto [g, r] :
           {std::pair{got.from_start, ref.from_start}, std::pair{got.from_end, ref.from_end}}) {
        const double gd = g.displacement / (h * h), gv = g.velocity / h;
        const double size = std::hypot(r.displacement * x, r.velocity);
        SCOPED_TRACE(::testing::Message() << "zeta " << zeta << " omega*h " << x);
        EXPECT_NEAR(gd * x, r.displacement * x, 32.0 * kEps * cond * size);
        EXPECT_NEAR(gv, r.velocity, 32.0 * kEps * cond * size);
      }
    }
  }
}

TEST(LinearForcingStep, ConstantForceHasTheStaticDeflectionAsFixedPoint) {
  // Under a constant force F the static state (F/ω², 0) must map to itself exactly: Φ·x* + (Γ₀+Γ₁)F
  // = x*. A property of the exact step that a zero-order-hold or trapezoid split also has, but
  // one that breaks if Γ₀ + Γ₁ is not ∫_0^h e^{rU}(0,1)ᵀ dr. Tolerance: a few roundings of x*.
  const double h = 1.0 / 48000.0;
  for (double zeta : {0.0, 0.3, 1.0, 5.0}) {
    for (double f_mode : {20.0, 900.0, 15000.0}) {
      const double omega = 2.0 * 3.141592653589793 * f_mode;
      const LinearForcingStep s = make_linear_forcing_step(omega, zeta, h);
      const ModeState rest{2.0 / (omega * omega), 0.0};
      ModeState x = rest;
      for (int n = 0; n < 1000; ++n) x = s.advance(x, 2.0, 2.0);
      EXPECT_NEAR(x.displacement, rest.displacement, 1e-12 * rest.displacement)
          << "zeta " << zeta << " mode " << f_mode;
      EXPECT_NEAR(x.velocity, 0.0, 1e-12 * rest.displacement * omega);
    }
  }
}

}  // namespace
}  // namespace nibrig::model::modal
