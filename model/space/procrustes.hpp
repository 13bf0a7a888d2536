// Aligning one configuration of points onto another by translation and rotation (or reflection),
// without scaling: how a refitted or recovered space is compared with a reference (bootstrap,
// synthetic recovery), since the objective leaves the rotation free when λ = 0.
#pragma once

#include <Eigen/Core>

namespace nibrig::model::space {

// `moving` (dims × points) translated and rotated onto `target` in the least-squares sense
// (orthogonal Procrustes via the SVD of the cross-covariance).
Eigen::MatrixXd procrustes_align(const Eigen::MatrixXd& moving, const Eigen::MatrixXd& target);

}  // namespace nibrig::model::space
