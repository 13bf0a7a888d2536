// The quadratic (10-node, P2) isoparametric tetrahedron: shape functions on the reference
// tetrahedron, the quadrature rules the element integrals use, the element stiffness and
// consistent mass, and the check that rejects inverted or degenerate elements.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "model/mechanics/isotropic_material.hpp"
#include "model/mechanics/tet_mesh.hpp"

namespace nibrig::model::mechanics {

// Reference tetrahedron: corners (0,0,0) (1,0,0) (0,1,0) (0,0,1), volume 1/6; ξ = (ξ1, ξ2, ξ3).
// Node order as in tet_mesh.hpp (Gmsh Tetrahedron10). Element DOF 3a + c is component c of node a,
// mirroring the global numbering 3·node + c.
using Tet10Nodes = Eigen::Matrix<double, 3, 10>;          // node positions as columns, m
using Tet10Shape = Eigen::Matrix<double, 10, 1>;          // N_a(ξ)
using Tet10ShapeGradient = Eigen::Matrix<double, 10, 3>;  // ∂N_a/∂ξ_k
using Tet10Matrix = Eigen::Matrix<double, 30, 30>;        // element stiffness or mass
using Tet10ScalarMatrix = Eigen::Matrix<double, 10, 10>;  // one block per pair of nodes

struct TetQuadrature {
  std::vector<Eigen::Vector3d> points;  // reference coordinates
  std::vector<double> weights;          // sum to 1/6, the reference volume
  int degree = 0;                       // polynomials up to this degree are integrated exactly
};

// 4 points, degree 2, equal weights. On a straight P2 element ∇N is linear and det J constant, so
// the stiffness integrand is quadratic and this rule is exact. On curved elements the integrand is
// rational and no rule is exact; a rule exact for degree 2k−2 = 2 keeps the optimal convergence
// order of isoparametric P2 elements (Ciarlet & Raviart 1972), which the cantilever test checks.
const TetQuadrature& tet_quadrature_degree2();

// 14 points, degree 5, all weights positive (the rule in Walkington 2000, "Quadrature on
// simplices of arbitrary dimension"; its exactness is checked on monomials in the tests). The
// consistent mass N_a N_b det J is of degree 4 on straight elements, so it is exact there; the
// positive weights keep the mass matrix positive definite, which Keast's 11-point degree-4 rule
// (negative weight at the centroid) does not guarantee.
const TetQuadrature& tet_quadrature_degree5();

Tet10Shape tet10_shape(const Eigen::Vector3d& xi);
Tet10ShapeGradient tet10_shape_gradient(const Eigen::Vector3d& xi);

// x(ξ) = Σ_a x_a N_a(ξ) and its Jacobian J_jk = ∂x_j/∂ξ_k.
Eigen::Vector3d tet10_position(const Tet10Nodes& x, const Eigen::Vector3d& xi);
Eigen::Matrix3d tet10_jacobian(const Tet10Nodes& x, const Eigen::Vector3d& xi);

// Smallest det J (m³) over the four corners and the points of both quadrature rules: the places
// where the element's integrals and point evaluation look. Positive for a valid element.
double tet10_min_jacobian_determinant(const Tet10Nodes& x);

// Throws std::invalid_argument naming the element when det J ≤ 1e-10 ℓ³ anywhere checked above (ℓ
// the longest corner-to-corner edge): inverted (negative) or collapsed (zero volume to round-off).
// A valid straight tetrahedron has det J = 6V, which is ≥ 1e-10 ℓ³ unless it is a sliver flatter
// than any mesher produces.
void check_tet10(const Tet10Nodes& x, std::size_t element_index);

// ∫ B^T C B dV with C isotropic, written per node pair with the Lamé parameters:
// K_ab,ij = ∫ λ ∂_i N_a ∂_j N_b + μ ∂_j N_a ∂_i N_b + μ δ_ij ∇N_a·∇N_b dV (N/m). Degree-2 rule.
// The element must pass check_tet10 (throws std::invalid_argument otherwise).
Tet10Matrix tet10_stiffness(const Tet10Nodes& x, const LameParameters& lame);

// Consistent mass per component, ρ ∫ N_a N_b dV (kg); the 30×30 mass is this block ⊗ I₃.
// Degree-5 rule.
Tet10ScalarMatrix tet10_scalar_mass(const Tet10Nodes& x, double density);
Tet10Matrix tet10_mass(const Tet10Nodes& x, double density);

// The positions of element e's nodes.
Tet10Nodes tet10_nodes(const TetMesh& mesh, std::size_t element);

}  // namespace nibrig::model::mechanics
