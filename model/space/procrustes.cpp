#include "model/space/procrustes.hpp"

#include <Eigen/SVD>
#include <stdexcept>

namespace nibrig::model::space {

Eigen::MatrixXd procrustes_align(const Eigen::MatrixXd& moving, const Eigen::MatrixXd& target) {
  if (moving.rows() != target.rows() || moving.cols() != target.cols() || moving.cols() == 0)
    throw std::invalid_argument(
        "Procrustes: the two configurations must have the same, non-zero shape");
  const Eigen::VectorXd moving_centre = moving.rowwise().mean(),
                        target_centre = target.rowwise().mean();
  const Eigen::MatrixXd a = moving.colwise() - moving_centre, b = target.colwise() - target_centre;
  // Minimise ‖R a − b‖ over orthogonal R: R = U Vᵀ for b aᵀ = U Σ Vᵀ.
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(b * a.transpose(),
                                              Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::MatrixXd rotation = svd.matrixU() * svd.matrixV().transpose();
  return (rotation * a).colwise() + target_centre;
}

}  // namespace nibrig::model::space
