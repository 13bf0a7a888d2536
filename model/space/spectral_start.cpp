#include "model/space/spectral_start.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace nibrig::model::space {

Eigen::MatrixXd spectral_start(const SpaceProblem& p, double radius) {
  const auto n = static_cast<Eigen::Index>(p.stimuli);
  const auto dims = static_cast<Eigen::Index>(p.dims);
  if (p.stimuli > kSpectralStartMaxStimuli || n <= dims) return {};
  // near(i, j): answers that took j as the closer candidate to reference i (or i to j); far: the
  // answers that took the other candidate over it.
  Eigen::MatrixXd near = Eigen::MatrixXd::Zero(n, n), far = Eigen::MatrixXd::Zero(n, n);
  for (const auto& t : p.triplets) {
    const auto r = static_cast<Eigen::Index>(t.reference), a = static_cast<Eigen::Index>(t.a),
               b = static_cast<Eigen::Index>(t.b);
    near(r, a) += t.count_a, far(r, a) += t.count_b;
    near(r, b) += t.count_b, far(r, b) += t.count_a;
  }
  const Eigen::MatrixXd seen_near = near + near.transpose(), seen_far = far + far.transpose();
  Eigen::MatrixXd squared(n, n);
  double sum = 0.0;
  Eigen::Index measured = 0;
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index i = 0; i < n; ++i) {
      const double seen = seen_near(i, j) + seen_far(i, j);
      squared(i, j) = -1.0;  // not measured
      if (i == j || seen == 0) continue;
      const double d = (seen_far(i, j) + 0.5) / (seen + 1.0);
      squared(i, j) = d * d;
      sum += d, ++measured;
    }
  if (measured == 0) return {};
  const double mean = sum / static_cast<double>(measured);
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index i = 0; i < n; ++i)
      if (squared(i, j) < 0) squared(i, j) = i == j ? 0.0 : mean * mean;
  // B = −½ J D² J with J = I − 11ᵀ/n; its largest eigenpairs give the coordinates.
  const Eigen::VectorXd row_mean = squared.rowwise().mean();
  const double total_mean = row_mean.mean();
  Eigen::MatrixXd gram(n, n);
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index i = 0; i < n; ++i)
      gram(i, j) = -0.5 * (squared(i, j) - row_mean(i) - row_mean(j) + total_mean);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(gram);
  if (eigen.info() != Eigen::Success) return {};
  Eigen::MatrixXd q(dims, n);
  for (Eigen::Index d = 0; d < dims; ++d) {
    const Eigen::Index k = n - 1 - d;  // eigenvalues ascend
    const double value = eigen.eigenvalues()(k);
    if (!(value > 0)) return {};
    q.row(d) = std::sqrt(value) * eigen.eigenvectors().col(k).transpose();
  }
  q = q.colwise() - q.rowwise().mean();
  const double rms = std::sqrt(q.colwise().squaredNorm().mean());
  if (!(rms > 0) || !std::isfinite(rms)) return {};
  return q * (radius / rms);
}

}  // namespace nibrig::model::space
