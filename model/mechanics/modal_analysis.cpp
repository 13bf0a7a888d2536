#include "model/mechanics/modal_analysis.hpp"

#include <Spectra/SymGEigsShiftSolver.h>
#include <spdlog/spdlog.h>

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace nibrig::model::mechanics {
namespace {

// y = (K − σM)⁻¹ x for Spectra. Spectra's own SymShiftInvert factorises a sparse K − σM with
// SparseLU, which ignores symmetry; a simplicial LDLᵀ with AMD ordering needs half the memory and
// about half the work, and K − σM is positive definite for σ < 0, so no pivoting is needed.
class ShiftInvertLdlt {
 public:
  using Scalar = double;

  ShiftInvertLdlt(const Eigen::SparseMatrix<double>& k, const Eigen::SparseMatrix<double>& m)
      : k_(k), m_(m) {}

  Eigen::Index rows() const { return k_.rows(); }
  Eigen::Index cols() const { return k_.cols(); }

  void set_shift(const double& sigma) {
    const Eigen::SparseMatrix<double> shifted = k_ - sigma * m_;
    ldlt_.compute(shifted);
    if (ldlt_.info() != Eigen::Success) {
      std::ostringstream s;
      s << "modal analysis: K - sigma M (sigma = " << sigma << " rad^2/s^2, " << k_.rows()
        << " DOFs) could not be factorised";
      throw std::runtime_error(s.str());
    }
  }

  void perform_op(const double* x_in, double* y_out) const {
    Eigen::Map<const Eigen::VectorXd> x(x_in, rows());
    Eigen::Map<Eigen::VectorXd> y(y_out, rows());
    y.noalias() = ldlt_.solve(x);
  }

 private:
  const Eigen::SparseMatrix<double>& k_;
  const Eigen::SparseMatrix<double>& m_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> ldlt_;
};

// y = M x for Spectra, which needs about six products with M per Lanczos step (the op and the
// M-inner products of its orthogonalisation). The consistent mass does not couple components, so
// M = M_s ⊗ I₃ with M_s the scalar mass over free nodes, and with x read as a row-major
// (nodes × 3) matrix X (free DOF 3k + c) the product is M_s X: a third of the memory traffic of M
// x. (Spectra's SparseSymMatProd goes through a self-adjoint view of one triangle and measured ten
// times slower than that.)
class MassProduct {
 public:
  using Scalar = double;
  using NodeMatrix = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

  explicit MassProduct(const Eigen::SparseMatrix<double>& m) : n_(m.rows()) {
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(static_cast<std::size_t>(m.nonZeros() / 3));
    for (Eigen::Index col = 0; col < m.outerSize(); col += 3)
      for (Eigen::SparseMatrix<double>::InnerIterator it(m, col); it; ++it)
        entries.emplace_back(static_cast<int>(it.row() / 3), static_cast<int>(col / 3), it.value());
    scalar_.resize(n_ / 3, n_ / 3);
    scalar_.setFromTriplets(entries.begin(), entries.end());
  }

  Eigen::Index rows() const { return n_; }
  Eigen::Index cols() const { return n_; }

  void perform_op(const double* x_in, double* y_out) const {
    Eigen::Map<const NodeMatrix> x(x_in, n_ / 3, 3);
    Eigen::Map<NodeMatrix> y(y_out, n_ / 3, 3);
    y.noalias() = scalar_ * x;
  }

  Eigen::MatrixXd operator*(const Eigen::Ref<const Eigen::MatrixXd>& x) const {
    Eigen::MatrixXd y(x.rows(), x.cols());
    for (Eigen::Index j = 0; j < x.cols(); ++j) perform_op(x.col(j).data(), y.col(j).data());
    return y;
  }

 private:
  Eigen::Index n_;
  Eigen::SparseMatrix<double> scalar_;
};

}  // namespace

ModalResult compute_modes(const FemSystem& system, const ModalOptions& options) {
  const Eigen::Index n = system.free_dofs();
  if (options.modes < 1 || options.modes >= n) {
    std::ostringstream s;
    s << "modal analysis: " << options.modes << " modes requested, must be in [1, " << n - 1
      << "] for " << n << " free DOFs";
    throw std::invalid_argument(s.str());
  }
  if (!std::isfinite(options.shift) || !(options.tolerance > 0.0) || options.max_restarts < 0) {
    std::ostringstream s;
    s << "modal analysis: bad options (shift " << options.shift << " rad^2/s^2, tolerance "
      << options.tolerance << ", max_restarts " << options.max_restarts << ")";
    throw std::invalid_argument(s.str());
  }
  const Eigen::Index basis =
      options.basis_size > 0 ? std::clamp<Eigen::Index>(options.basis_size, options.modes + 1, n)
                             : std::min<Eigen::Index>(n, 2 * options.modes + 1);

  ShiftInvertLdlt op(system.stiffness, system.mass);
  MassProduct mass_op(system.mass);
  Spectra::SymGEigsShiftSolver<ShiftInvertLdlt, MassProduct, Spectra::GEigsMode::ShiftInvert>
      solver(op, mass_op, options.modes, basis, options.shift);
  solver.init();
  // In shift-invert mode the largest |1/(λ − σ)| are the λ nearest σ; with σ below the spectrum
  // these are the lowest modes. Sorted ascending in λ on return.
  const Eigen::Index converged =
      solver.compute(Spectra::SortRule::LargestMagn, options.max_restarts, options.tolerance,
                     Spectra::SortRule::SmallestAlge);
  if (solver.info() != Spectra::CompInfo::Successful) {
    std::ostringstream s;
    s << "modal analysis did not converge: " << converged << " of " << options.modes
      << " modes after " << solver.num_iterations() - 1 << " Lanczos restarts (" << n
      << " free DOFs, basis " << basis << ", tolerance " << options.tolerance << ")";
    throw std::runtime_error(s.str());
  }

  const Eigen::VectorXd lambda = solver.eigenvalues();
  Eigen::MatrixXd vectors = solver.eigenvectors();
  ModalResult result;
  result.omega.resize(lambda.size());
  for (Eigen::Index i = 0; i < lambda.size(); ++i) {
    const double omega = std::sqrt(std::max(lambda(i), 0.0));
    const double f = omega / (2.0 * std::numbers::pi);
    if (!(f >= 1e-3)) {
      std::ostringstream s;
      s << "modal analysis: mode " << i + 1 << " has eigenvalue " << lambda(i)
        << " rad^2/s^2 (frequency " << f
        << " Hz): a rigid-body motion or mechanism; the held nodes do not hold the body";
      throw std::runtime_error(s.str());
    }
    result.omega(i) = omega;
    // Spectra's vectors are M-orthonormal already (its Lanczos runs in the M inner product);
    // normalising again removes the last round-off so that φᵀMφ = 1 holds to machine precision.
    const double norm2 = vectors.col(i).dot(system.mass * vectors.col(i));
    // A mode's sign is arbitrary; fixing it (largest component positive) makes results
    // reproducible and comparable between runs and meshes.
    Eigen::Index largest = 0;
    vectors.col(i).cwiseAbs().maxCoeff(&largest);
    vectors.col(i) /= std::copysign(std::sqrt(norm2), vectors(largest, i));
  }
  result.frequency_hz = result.omega / (2.0 * std::numbers::pi);
  result.shapes = system.expand(vectors);
  result.restarts = static_cast<int>(solver.num_iterations()) - 1;
  result.solves = static_cast<int>(solver.num_operations());
  spdlog::debug("modal analysis: {} modes of {} free DOFs, {} to {} Hz, {} solves", lambda.size(),
                n, result.frequency_hz(0), result.frequency_hz(lambda.size() - 1), result.solves);
  return result;
}

}  // namespace nibrig::model::mechanics
