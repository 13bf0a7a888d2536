#include "model/mechanics/tet10_element.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace nibrig::model::mechanics {
namespace {

// Edge node k (4..9) lies between corners kEdges[k-4].
constexpr std::array<std::array<int, 2>, 6> kEdges{
    {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {2, 3}, {1, 3}}};

// Barycentric coordinates (L0, L1, L2, L3) → reference point (L1, L2, L3).
Eigen::Vector3d from_barycentric(double l0, double l1, double l2, double l3) {
  (void)l0;  // implied by the other three; kept in the signature so call sites read as 4-tuples
  return {l1, l2, l3};
}

TetQuadrature make_degree2() {
  TetQuadrature q;
  q.degree = 2;
  const double a = (5.0 - std::sqrt(5.0)) / 20.0;
  const double b = 1.0 - 3.0 * a;
  q.points = {from_barycentric(b, a, a, a), from_barycentric(a, b, a, a),
              from_barycentric(a, a, b, a), from_barycentric(a, a, a, b)};
  q.weights.assign(4, 1.0 / 24.0);
  return q;
}

TetQuadrature make_degree5() {
  TetQuadrature q;
  q.degree = 5;
  // Two orbits of 4 points (a, a, a, 1−3a) and one of 6 points (a, a, ½−a, ½−a).
  const auto add_orbit4 = [&q](double a, double w) {
    const double b = 1.0 - 3.0 * a;
    for (const auto& p : {from_barycentric(b, a, a, a), from_barycentric(a, b, a, a),
                          from_barycentric(a, a, b, a), from_barycentric(a, a, a, b)}) {
      q.points.push_back(p);
      q.weights.push_back(w);
    }
  };
  add_orbit4(0.3108859192633006097973457337635, 0.01878132095300264179986427538880);
  add_orbit4(0.09273525031089122640232391373703, 0.01224884051939365825728503424772);
  const double a = 0.04550370412564964949188052627933, b = 0.5 - a;
  const double w = 0.007091003462846911073011571353370;
  for (const auto& p :
       {from_barycentric(a, a, b, b), from_barycentric(a, b, a, b), from_barycentric(a, b, b, a),
        from_barycentric(b, a, a, b), from_barycentric(b, a, b, a), from_barycentric(b, b, a, a)}) {
    q.points.push_back(p);
    q.weights.push_back(w);
  }
  return q;
}

// Jacobian determinant and shape gradients with respect to x at one point; throws on det J ≤ 0
// because every integral below divides by it.
struct PointGeometry {
  double det_j = 0.0;
  Tet10ShapeGradient gradient_x;  // ∂N_a/∂x_j
};

PointGeometry point_geometry(const Tet10Nodes& x, const Eigen::Vector3d& xi) {
  const Tet10ShapeGradient d = tet10_shape_gradient(xi);
  const Eigen::Matrix3d j = x * d;
  PointGeometry g;
  g.det_j = j.determinant();
  if (!(g.det_j > 0.0)) {
    std::ostringstream s;
    s << "tet10 element: Jacobian determinant " << g.det_j << " m^3 at reference point (" << xi.x()
      << ", " << xi.y() << ", " << xi.z() << ") is not positive (inverted element)";
    throw std::invalid_argument(s.str());
  }
  g.gradient_x = d * j.inverse();
  return g;
}

}  // namespace

const TetQuadrature& tet_quadrature_degree2() {
  static const TetQuadrature rule = make_degree2();
  return rule;
}

const TetQuadrature& tet_quadrature_degree5() {
  static const TetQuadrature rule = make_degree5();
  return rule;
}

Tet10Shape tet10_shape(const Eigen::Vector3d& xi) {
  const std::array<double, 4> l{1.0 - xi.sum(), xi.x(), xi.y(), xi.z()};
  Tet10Shape n;
  for (int c = 0; c < 4; ++c) n(c) = l[c] * (2.0 * l[c] - 1.0);
  for (int k = 0; k < 6; ++k) n(4 + k) = 4.0 * l[kEdges[k][0]] * l[kEdges[k][1]];
  return n;
}

Tet10ShapeGradient tet10_shape_gradient(const Eigen::Vector3d& xi) {
  const std::array<double, 4> l{1.0 - xi.sum(), xi.x(), xi.y(), xi.z()};
  // ∂L_c/∂ξ: L0 = 1 − ξ1 − ξ2 − ξ3, L_c = ξ_c otherwise.
  const std::array<Eigen::RowVector3d, 4> dl{
      Eigen::RowVector3d(-1.0, -1.0, -1.0), Eigen::RowVector3d(1.0, 0.0, 0.0),
      Eigen::RowVector3d(0.0, 1.0, 0.0), Eigen::RowVector3d(0.0, 0.0, 1.0)};
  Tet10ShapeGradient g;
  for (int c = 0; c < 4; ++c) g.row(c) = (4.0 * l[c] - 1.0) * dl[c];
  for (int k = 0; k < 6; ++k) {
    const int a = kEdges[k][0], b = kEdges[k][1];
    g.row(4 + k) = 4.0 * (l[a] * dl[b] + l[b] * dl[a]);
  }
  return g;
}

Eigen::Vector3d tet10_position(const Tet10Nodes& x, const Eigen::Vector3d& xi) {
  return x * tet10_shape(xi);
}

Eigen::Matrix3d tet10_jacobian(const Tet10Nodes& x, const Eigen::Vector3d& xi) {
  return x * tet10_shape_gradient(xi);
}

double tet10_min_jacobian_determinant(const Tet10Nodes& x) {
  double lowest = std::numeric_limits<double>::infinity();
  const auto visit = [&](const Eigen::Vector3d& xi) {
    lowest = std::min(lowest, tet10_jacobian(x, xi).determinant());
  };
  visit(Eigen::Vector3d::Zero());
  for (int k = 0; k < 3; ++k) visit(Eigen::Vector3d::Unit(k));
  for (const auto& p : tet_quadrature_degree2().points) visit(p);
  for (const auto& p : tet_quadrature_degree5().points) visit(p);
  return lowest;
}

void check_tet10(const Tet10Nodes& x, std::size_t element_index) {
  double longest = 0.0;
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b) longest = std::max(longest, (x.col(a) - x.col(b)).norm());
  const double det = tet10_min_jacobian_determinant(x);
  if (!std::isfinite(det) || !std::isfinite(longest) || longest == 0.0 ||
      det <= 1e-10 * longest * longest * longest) {
    std::ostringstream s;
    s << "element " << element_index << " is " << (det < 0.0 ? "inverted" : "degenerate")
      << ": smallest Jacobian determinant " << det << " m^3 (longest edge " << longest << " m)";
    throw std::invalid_argument(s.str());
  }
}

Tet10Matrix tet10_stiffness(const Tet10Nodes& x, const LameParameters& lame) {
  Tet10Matrix k = Tet10Matrix::Zero();
  const TetQuadrature& rule = tet_quadrature_degree2();
  for (std::size_t q = 0; q < rule.points.size(); ++q) {
    const PointGeometry g = point_geometry(x, rule.points[q]);
    const double w = rule.weights[q] * g.det_j;
    const Tet10ShapeGradient& d = g.gradient_x;
    const Tet10ScalarMatrix dots = d * d.transpose();
    for (int b = 0; b < 10; ++b) {
      for (int a = 0; a < 10; ++a) {
        auto block = k.block<3, 3>(3 * a, 3 * b);
        block.noalias() += (w * lame.lambda) * d.row(a).transpose() * d.row(b);
        block.noalias() += (w * lame.mu) * d.row(b).transpose() * d.row(a);
        block.diagonal().array() += w * lame.mu * dots(a, b);
      }
    }
  }
  return k;
}

Tet10ScalarMatrix tet10_scalar_mass(const Tet10Nodes& x, double density) {
  Tet10ScalarMatrix m = Tet10ScalarMatrix::Zero();
  const TetQuadrature& rule = tet_quadrature_degree5();
  for (std::size_t q = 0; q < rule.points.size(); ++q) {
    const double det = tet10_jacobian(x, rule.points[q]).determinant();
    if (!(det > 0.0)) (void)point_geometry(x, rule.points[q]);  // throws with the details
    const Tet10Shape n = tet10_shape(rule.points[q]);
    m.noalias() += (density * rule.weights[q] * det) * n * n.transpose();
  }
  return m;
}

Tet10Matrix tet10_mass(const Tet10Nodes& x, double density) {
  const Tet10ScalarMatrix s = tet10_scalar_mass(x, density);
  Tet10Matrix m = Tet10Matrix::Zero();
  for (int b = 0; b < 10; ++b)
    for (int a = 0; a < 10; ++a)
      for (int c = 0; c < 3; ++c) m(3 * a + c, 3 * b + c) = s(a, b);
  return m;
}

Tet10Nodes tet10_nodes(const TetMesh& mesh, std::size_t element) {
  Tet10Nodes x;
  const Tet10& t = mesh.tets[element];
  for (int a = 0; a < 10; ++a) x.col(a) = mesh.nodes.col(t[a]);
  return x;
}

}  // namespace nibrig::model::mechanics
