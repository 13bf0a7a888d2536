// Euler-Bernoulli beam theory for a clamped-free rectangular bar: the closed form the FEM is
// checked against (a plain bar without cutout) and that the demo and `nibrig mechanics modes --bar`
// report beside the computed frequencies.
#pragma once

#include <vector>

namespace nibrig::model::mechanics {

// β_n L of the first n roots of cos(βL)·cosh(βL) = −1 (1.8751, 4.6941, 7.8548, ...), solved
// numerically to full double precision.
std::vector<double> cantilever_roots(int n);

// Bending frequencies (Hz) in the direction of `thickness`: f_n = (β_n L)² / (2π L²) · √(E I / (ρ
// A)), I = width·thickness³/12, A = width·thickness. Slender-beam theory: shear and rotary inertia
// are neglected (error of order (thickness/L)²) and so is the stiffening of a wide bar at its
// clamp.
std::vector<double> cantilever_bending_frequencies(double youngs_modulus, double density,
                                                   double free_length, double width,
                                                   double thickness, int n);

}  // namespace nibrig::model::mechanics
