// Evaluating a nodal field of a quadratic tetrahedral mesh at an arbitrary point: find the element
// holding the point (Newton inversion of the isoparametric map, with a uniform grid to find
// candidates) and the ten shape-function weights there; used to read a mode shape at the stylus
// tip and at the sensor.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "model/mechanics/tet10_element.hpp"
#include "model/mechanics/tet_mesh.hpp"

namespace nibrig::model::mechanics {

struct PointLocation {
  std::size_t element = 0;
  Eigen::Vector3d reference = Eigen::Vector3d::Zero();  // ξ in the element's reference tetrahedron
  Tet10Shape weights = Tet10Shape::Zero();              // N_a(ξ), summing to 1
  // Distance (m) from the asked point to the point of the body used: 0 (to round-off) inside,
  // up to the boundary tolerance for a point just off the surface.
  double distance = 0.0;
};

// Builds the search grid once; `mesh` must outlive the locator.
class PointLocator {
 public:
  // Throws std::invalid_argument on an empty mesh or an inverted/degenerate element.
  explicit PointLocator(const TetMesh& mesh);
  explicit PointLocator(TetMesh&&) = delete;  // would keep a reference to a temporary

  // The element and reference coordinates of `point` (m). A point outside the discretised body
  // by at most 5 % of the nearest element's longest edge is taken at the nearest point of the body:
  // a point on the true curved surface (a tip apex) may lie that little outside the quadratic
  // surface, whose geometric error is O(h³/R²), far below 5 % of h unless the radius of curvature
  // R is below the element size h. Farther out, throws std::invalid_argument
  // "point (x, y, z) m is outside the body: nearest surface is N mm away".
  PointLocation locate(const Eigen::Vector3d& point) const;

  const TetMesh& mesh() const { return mesh_; }

 private:
  struct Candidate;
  Candidate closest_in_element(std::size_t element, const Eigen::Vector3d& point) const;

  const TetMesh& mesh_;
  std::vector<Eigen::Vector3d> box_low_, box_high_;  // per element, inflated (see .cpp)
  std::vector<double> size_;                         // per element, longest corner edge, m
  Eigen::Vector3d grid_origin_ = Eigen::Vector3d::Zero();
  double cell_ = 1.0;
  Eigen::Vector3i cells_ = Eigen::Vector3i::Ones();
  std::vector<int> cell_start_, cell_items_;  // elements whose inflated box meets each cell
};

// Value at a located point of a field given at the nodes (3 components per node, DOF 3·node + c),
// e.g. one column of ModalResult::shapes.
Eigen::Vector3d evaluate(const TetMesh& mesh, const PointLocation& at,
                         const Eigen::Ref<const Eigen::VectorXd>& nodal_field);

// For every column of `nodal_fields`, the value at the point projected on `direction`.
Eigen::VectorXd evaluate_along(const TetMesh& mesh, const PointLocation& at,
                               const Eigen::MatrixXd& nodal_fields,
                               const Eigen::Vector3d& direction);

}  // namespace nibrig::model::mechanics
