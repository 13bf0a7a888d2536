#include "model/mechanics/mode_direction.hpp"

namespace nibrig::model::mechanics {

std::array<double, 3> displacement_fractions(const Eigen::Ref<const Eigen::VectorXd>& shape) {
  std::array<double, 3> sums{0.0, 0.0, 0.0};
  for (Eigen::Index dof = 0; dof < shape.size(); ++dof)
    sums[static_cast<std::size_t>(dof % 3)] += shape[dof] * shape[dof];
  const double total = sums[0] + sums[1] + sums[2];
  for (double& v : sums) v = total > 0 ? v / total : 0.0;
  return sums;
}

}  // namespace nibrig::model::mechanics
