#include "model/mechanics/beam_theory.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace nibrig::model::mechanics {
namespace {

TEST(BeamTheory, RootsAreTheTabulatedOnes) {
  // Published values (e.g. Blevins, Formulas for Natural Frequency and Mode Shape, Table 8-1), to
  // the 9 digits they are printed with; higher roots approach (2k − 1)π/2.
  const auto roots = cantilever_roots(5);
  EXPECT_NEAR(roots[0], 1.87510407, 5e-9);
  EXPECT_NEAR(roots[1], 4.69409113, 5e-9);
  EXPECT_NEAR(roots[2], 7.85475744, 5e-9);
  EXPECT_NEAR(roots[3], 10.99554073, 5e-9);
  EXPECT_NEAR(roots[4], 14.13716839, 5e-9);
  // The same equation in its well-conditioned form cos r = −1/cosh r (cosh grows like e^r).
  for (double r : roots) EXPECT_NEAR(std::cos(r), -1.0 / std::cosh(r), 1e-14);
}

TEST(BeamTheory, SteelRulerFrequencyByHand) {
  // 300 × 25 × 1 mm steel, E = 200 GPa, ρ = 7850: √(EI/ρA) = t·√(E/12ρ) = 1e-3·√(200e9/94200)
  // = 1.45710 m²/s; f1 = 1.875104² · 1.45710 / (2π · 0.09) = 9.0598 Hz (by hand, 5 digits).
  const auto f = cantilever_bending_frequencies(200e9, 7850, 0.3, 0.025, 0.001, 2);
  EXPECT_NEAR(f[0], 9.0598, 0.0001);
  // The tabulated roots carry 9 digits (±5e-9, i.e. 3e-9 relative on the first): their ratio
  // squared is good to about 1e-8 relative, 6e-8 absolute.
  EXPECT_NEAR(f[1] / f[0], std::pow(4.69409113 / 1.87510407, 2), 1e-7);
  EXPECT_THROW(cantilever_bending_frequencies(-1, 7850, 0.3, 0.025, 0.001, 2),
               std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::model::mechanics
