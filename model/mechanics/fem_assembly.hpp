// Assembly of the global stiffness K and consistent mass M of a quadratic tetrahedral mesh with a
// material per region, and elimination of the nodes held fixed (Dirichlet conditions from named
// node sets) by assembling only the free degrees of freedom.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "model/mechanics/isotropic_material.hpp"
#include "model/mechanics/tet_mesh.hpp"

namespace nibrig::model::mechanics {

// K and M over the free DOFs. A held node has all three components fixed at zero. Free DOFs keep
// the mesh's order: free DOF 3·k + c is component c of the k-th free node, so with nothing held
// the numbering is the full one, DOF = 3·node + c. Both matrices store both triangles.
struct FemSystem {
  Eigen::SparseMatrix<double> stiffness;  // N/m
  Eigen::SparseMatrix<double> mass;       // kg
  std::vector<int> free_to_full;          // free DOF → full DOF
  std::vector<int> full_to_free;          // full DOF → free DOF, −1 where the node is held

  Eigen::Index free_dofs() const { return stiffness.rows(); }
  Eigen::Index full_dofs() const { return static_cast<Eigen::Index>(full_to_free.size()); }

  // Columns over free DOFs → columns over full DOFs, zero at held DOFs.
  Eigen::MatrixXd expand(const Eigen::MatrixXd& free_values) const;
};

// region_materials[r] is the material of mesh.region_names[r]. held_node_sets names the node sets
// held fixed (e.g. {"clamp"}); an empty list assembles the unconstrained body, whose K has the six
// rigid-body motions in its null space (useful for checks, not for modal analysis).
// Throws std::invalid_argument on: materials and regions of different counts, an invalid material,
// a tet or region index out of range, a node in no element (its mass would be zero), a named node
// set that is missing or empty (a clamp that holds nothing leaves six zero-frequency modes), an
// inverted or degenerate element (message names the element), or every node held.
FemSystem assemble(const TetMesh& mesh, const std::vector<IsotropicMaterial>& region_materials,
                   const std::vector<std::string>& held_node_sets);

}  // namespace nibrig::model::mechanics
