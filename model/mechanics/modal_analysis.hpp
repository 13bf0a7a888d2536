// The lowest vibration modes of an assembled, clamped body: the generalized eigenproblem
// K φ = ω² M φ over the free DOFs, solved by shift-and-invert Lanczos (Spectra) on a sparse LDLᵀ
// factorisation, with mass-normalised mode shapes expanded back to every DOF of the mesh.
#pragma once

#include <Eigen/Core>

#include "model/mechanics/fem_assembly.hpp"

namespace nibrig::model::mechanics {

struct ModalOptions {
  int modes = 64;  // how many of the lowest modes
  // Lanczos basis size; 0 picks min(free DOFs, 2·modes + 1). A larger basis means fewer restarts
  // (each a factorised solve per new vector) but more orthogonalisation work.
  int basis_size = 0;
  // Shift σ of K − σM, rad²/s². Slightly below zero keeps K − σM positive definite, so the LDLᵀ
  // factorisation has no pivoting problem even when the clamp barely holds the body, while it is
  // far below the lowest mode of any stylus (a 1 Hz mode is ω² ≈ 39.5) so the spectral
  // transformation still separates the lowest modes well. The modes returned are those nearest
  // the shift, which are the lowest only when it lies below them.
  double shift = -1.0;
  double tolerance = 1e-10;  // relative accuracy of the Ritz values (Spectra's tol), > 0
  int max_restarts = 1000;   // ≥ 0; restarts of the Lanczos basis before giving up
};

struct ModalResult {
  Eigen::VectorXd omega;         // ω_i, rad/s, ascending
  Eigen::VectorXd frequency_hz;  // ω_i / 2π
  // One column per mode over the full DOFs (3·node + component), φᵢᵀ M φᵢ = 1 with M the mass of
  // the free DOFs, zero at held DOFs. Unit kg^-½.
  Eigen::MatrixXd shapes;
  int restarts = 0;  // Lanczos restarts Spectra needed (0: the first basis held every mode)
  int solves = 0;    // applications of (K − σM)⁻¹ M
};

// Throws std::invalid_argument on a bad option (modes < 1 or ≥ free DOFs, a non-finite shift, a
// tolerance ≤ 0, negative restarts), std::runtime_error when
// K − σM cannot be factorised, when Lanczos does not converge (message says how many modes did), or
// when a mode has a frequency below 1 mHz: that is a rigid-body motion or a mechanism the held
// nodes do not stop, not a vibration.
ModalResult compute_modes(const FemSystem& system, const ModalOptions& options = {});

}  // namespace nibrig::model::mechanics
