#include "model/mechanics/point_probe.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace nibrig::model::mechanics {
namespace {

// Boundary tolerance and box inflation, as fractions of an element's longest edge. The box must
// hold the curved element (a quadratic edge bulges past its nodes by at most 1/8 of the edge node's
// offset from the chord, a few % of the edge at most) plus the tolerance.
constexpr double kBoundaryTolerance = 0.05;
constexpr double kBoxInflation = 0.1 + kBoundaryTolerance;
// A point this close (relative to the element size) to an element is inside it up to round-off.
constexpr double kInsideTolerance = 1e-10;

// Barycentric weights (of a, b, c) of the point of triangle abc nearest p (Ericson, Real-Time
// Collision Detection, 5.1.5: Voronoi regions of vertices, edges, face).
Eigen::Vector3d closest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                    const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return {1.0, 0.0, 0.0};
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return {0.0, 1.0, 0.0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double v = d1 / (d1 - d3);
    return {1.0 - v, v, 0.0};
  }
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return {0.0, 0.0, 1.0};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double w = d2 / (d2 - d6);
    return {1.0 - w, 0.0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0.0, 1.0 - w, w};
  }
  const double denom = 1.0 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  return {1.0 - v - w, v, w};
}

// One Gauss-Newton step: the reference point η of the tetrahedron nearest p under the element's
// map linearised at ξ, x(η) ≈ x(ξ) + J (η − ξ). Inside, this is Newton's step for x(η) = p;
// outside, the nearest point on the linearised tetrahedron's faces.
Eigen::Vector3d linearised_closest(const Eigen::Vector3d& p, const Eigen::Vector3d& x,
                                   const Eigen::Matrix3d& j, const Eigen::Vector3d& xi) {
  const Eigen::Vector3d eta = xi + j.partialPivLu().solve(p - x);
  const std::array<double, 4> mu{1.0 - eta.sum(), eta.x(), eta.y(), eta.z()};
  if (*std::min_element(mu.begin(), mu.end()) >= 0.0) return eta;
  std::array<Eigen::Vector3d, 4> ref{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(),
                                     Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ()};
  std::array<Eigen::Vector3d, 4> y;
  for (int k = 0; k < 4; ++k) y[k] = x + j * (ref[k] - xi);
  double best = std::numeric_limits<double>::infinity();
  Eigen::Vector3d best_eta = eta;
  for (int k = 0; k < 4; ++k) {
    if (mu[k] >= 0.0) continue;  // p is on the inner side of the face opposite corner k
    const int a = (k + 1) % 4, b = (k + 2) % 4, c = (k + 3) % 4;
    const Eigen::Vector3d w = closest_on_triangle(p, y[a], y[b], y[c]);
    const Eigen::Vector3d q = w(0) * y[a] + w(1) * y[b] + w(2) * y[c];
    const double d = (q - p).squaredNorm();
    if (d < best) {
      best = d;
      best_eta = w(0) * ref[a] + w(1) * ref[b] + w(2) * ref[c];
    }
  }
  return best_eta;
}

double box_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& low,
                    const Eigen::Vector3d& high) {
  return (p.cwiseMax(low).cwiseMin(high) - p).norm();
}

}  // namespace

struct PointLocator::Candidate {
  Eigen::Vector3d xi;
  double distance;
};

PointLocator::PointLocator(const TetMesh& mesh) : mesh_(mesh) {
  if (mesh.tets.empty()) throw std::invalid_argument("point probe: the mesh has no elements");
  const std::size_t n = mesh.tets.size();
  box_low_.resize(n);
  box_high_.resize(n);
  size_.resize(n);
  Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d high = -low;
  double size_sum = 0.0;
  for (std::size_t e = 0; e < n; ++e) {
    const Tet10Nodes x = tet10_nodes(mesh, e);
    check_tet10(x, e);
    double longest = 0.0;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) longest = std::max(longest, (x.col(a) - x.col(b)).norm());
    size_[e] = longest;
    size_sum += longest;
    const double pad = kBoxInflation * longest;
    box_low_[e] = x.rowwise().minCoeff().array() - pad;
    box_high_[e] = x.rowwise().maxCoeff().array() + pad;
    low = low.cwiseMin(box_low_[e]);
    high = high.cwiseMax(box_high_[e]);
  }
  // Cells of half the mean element size: each element meets a few dozen cells and each cell a
  // dozen or so elements. Coarser if the body's box would need more than 16 cells per element.
  cell_ = 0.5 * size_sum / static_cast<double>(n);
  const Eigen::Vector3d extent = high - low;
  while ((extent / cell_).array().ceil().prod() > 16.0 * static_cast<double>(n)) cell_ *= 1.5;
  grid_origin_ = low;
  for (int k = 0; k < 3; ++k)
    cells_(k) = std::max(1, static_cast<int>(std::ceil(extent(k) / cell_)));

  const auto cell_range = [&](std::size_t e, Eigen::Vector3i& from, Eigen::Vector3i& to) {
    for (int k = 0; k < 3; ++k) {
      from(k) = std::clamp(static_cast<int>((box_low_[e](k) - low(k)) / cell_), 0, cells_(k) - 1);
      to(k) = std::clamp(static_cast<int>((box_high_[e](k) - low(k)) / cell_), 0, cells_(k) - 1);
    }
  };
  const auto index = [&](int i, int j, int k) { return (k * cells_(1) + j) * cells_(0) + i; };
  cell_start_.assign(static_cast<std::size_t>(cells_.prod()) + 1, 0);
  Eigen::Vector3i from, to;
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<int> fill;
    if (pass == 1) {
      std::partial_sum(cell_start_.begin(), cell_start_.end(), cell_start_.begin());
      cell_items_.resize(static_cast<std::size_t>(cell_start_.back()));
      fill.assign(cell_start_.begin(), cell_start_.end() - 1);
    }
    for (std::size_t e = 0; e < n; ++e) {
      cell_range(e, from, to);
      for (int k = from(2); k <= to(2); ++k)
        for (int j = from(1); j <= to(1); ++j)
          for (int i = from(0); i <= to(0); ++i) {
            if (pass == 0)
              ++cell_start_[index(i, j, k) + 1];
            else
              cell_items_[fill[index(i, j, k)]++] = static_cast<int>(e);
          }
    }
  }
}

PointLocator::Candidate PointLocator::closest_in_element(std::size_t element,
                                                         const Eigen::Vector3d& point) const {
  const Tet10Nodes x = tet10_nodes(mesh_, element);
  Eigen::Vector3d xi = Eigen::Vector3d::Constant(0.25);
  double f = (tet10_position(x, xi) - point).squaredNorm();
  // Newton converges in a handful of steps inside a mildly curved element. Outside, the
  // Gauss-Newton step of the linearised tetrahedron overshoots when the point is farther away than
  // the surface's radius of curvature (a stylus tip seen from a centimetre away) and would stop at
  // a corner; halving the step until |x(ξ) − p| decreases makes every step a descent step (the
  // step is a descent direction and the reference tetrahedron is convex). Steps are measured in
  // reference units.
  for (int iteration = 0; iteration < 50; ++iteration) {
    const Eigen::Vector3d step =
        linearised_closest(point, tet10_position(x, xi), tet10_jacobian(x, xi), xi) - xi;
    double t = 1.0, f_next = f;
    Eigen::Vector3d next = xi;
    for (; t > 1e-6; t *= 0.5) {
      next = xi + t * step;
      f_next = (tet10_position(x, next) - point).squaredNorm();
      if (f_next <= f) break;
    }
    if (f_next > f) break;  // no descent left: xi is the constrained minimum to round-off
    xi = next;
    f = f_next;
    if (t * step.cwiseAbs().maxCoeff() < 1e-14) break;
  }
  return {xi, (tet10_position(x, xi) - point).norm()};
}

PointLocation PointLocator::locate(const Eigen::Vector3d& point) const {
  if (!point.allFinite()) throw std::invalid_argument("point probe: the point is not finite");
  bool found = false;
  PointLocation best;
  best.distance = std::numeric_limits<double>::infinity();
  const auto consider = [&](std::size_t e) {
    const Candidate c = closest_in_element(e, point);
    if (c.distance > kBoundaryTolerance * size_[e] || c.distance >= best.distance) return;
    found = true;
    best.element = e;
    best.reference = c.xi;
    best.distance = c.distance;
  };

  Eigen::Vector3i cell;
  bool in_grid = true;
  for (int k = 0; k < 3; ++k) {
    const double u = (point(k) - grid_origin_(k)) / cell_;
    in_grid = in_grid && u >= 0.0 && u <= cells_(k);
    cell(k) = std::clamp(static_cast<int>(u), 0, cells_(k) - 1);
  }
  if (in_grid) {
    const int c = (cell(2) * cells_(1) + cell(1)) * cells_(0) + cell(0);
    for (int i = cell_start_[c]; i < cell_start_[c + 1]; ++i) {
      const auto e = static_cast<std::size_t>(cell_items_[i]);
      if ((point.array() < box_low_[e].array()).any() ||
          (point.array() > box_high_[e].array()).any())
        continue;
      consider(e);
      if (found && best.distance <= kInsideTolerance * size_[best.element]) break;
    }
  }
  if (found) {
    best.weights = tet10_shape(best.reference);
    return best;
  }

  // Outside: the distance to the body for the message, over elements in order of a lower bound
  // (the distance to their box, which holds them).
  std::vector<std::pair<double, std::size_t>> order(mesh_.tets.size());
  for (std::size_t e = 0; e < order.size(); ++e)
    order[e] = {box_distance(point, box_low_[e], box_high_[e]), e};
  std::sort(order.begin(), order.end());
  double nearest = std::numeric_limits<double>::infinity();
  for (const auto& [bound, e] : order) {
    if (bound >= nearest) break;
    nearest = std::min(nearest, closest_in_element(e, point).distance);
  }
  std::ostringstream s;
  s << "point (" << point.x() << ", " << point.y() << ", " << point.z()
    << ") m is outside the body: nearest surface is " << nearest * 1e3 << " mm away";
  throw std::invalid_argument(s.str());
}

Eigen::Vector3d evaluate(const TetMesh& mesh, const PointLocation& at,
                         const Eigen::Ref<const Eigen::VectorXd>& nodal_field) {
  if (nodal_field.size() != 3 * mesh.nodes.cols()) {
    std::ostringstream s;
    s << "point probe: field has " << nodal_field.size() << " values, the mesh has "
      << 3 * mesh.nodes.cols() << " DOFs";
    throw std::invalid_argument(s.str());
  }
  Eigen::Vector3d value = Eigen::Vector3d::Zero();
  const Tet10& t = mesh.tets.at(at.element);
  for (int a = 0; a < 10; ++a) value += at.weights(a) * nodal_field.segment<3>(3 * t[a]);
  return value;
}

Eigen::VectorXd evaluate_along(const TetMesh& mesh, const PointLocation& at,
                               const Eigen::MatrixXd& nodal_fields,
                               const Eigen::Vector3d& direction) {
  Eigen::VectorXd out(nodal_fields.cols());
  for (Eigen::Index i = 0; i < nodal_fields.cols(); ++i)
    out(i) = direction.dot(evaluate(mesh, at, nodal_fields.col(i)));
  return out;
}

}  // namespace nibrig::model::mechanics
