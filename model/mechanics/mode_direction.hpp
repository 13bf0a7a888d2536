// Which way a mode moves: the share of its shape's squared nodal displacement along x, y and z.
// Tells bending in a bar's thickness (z) from its in-plane (y) and axial (x) modes without a
// picture; `mechanics modes` reports it per mode.
#pragma once

#include <Eigen/Core>
#include <array>

namespace nibrig::model::mechanics {

// `shape` holds x, y, z of each node in turn (ModalResult::shapes' columns). Shares add up to 1;
// all 0 for a zero shape.
std::array<double, 3> displacement_fractions(const Eigen::Ref<const Eigen::VectorXd>& shape);

}  // namespace nibrig::model::mechanics
