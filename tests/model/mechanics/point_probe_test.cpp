#include "model/mechanics/point_probe.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

#include "tests/model/mechanics/box_mesh.hpp"

namespace nibrig::model::mechanics {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

// An affine field u(p) = a + G p: every isoparametric element reproduces it exactly, curved or not.
struct LinearField {
  Eigen::Vector3d a{0.3, -0.2, 0.5};
  Eigen::Matrix3d g = (Eigen::Matrix3d() << 10, -4, 7, 3, 12, -5, -8, 6, 9).finished();
  Eigen::Vector3d operator()(const Eigen::Vector3d& p) const { return a + g * p; }
  Eigen::VectorXd nodal(const TetMesh& mesh) const {
    Eigen::VectorXd u(3 * mesh.nodes.cols());
    for (Eigen::Index n = 0; n < mesh.nodes.cols(); ++n)
      u.segment<3>(3 * n) = (*this)(mesh.nodes.col(n));
    return u;
  }
};

std::string locate_error(const PointLocator& locator, const Eigen::Vector3d& p) {
  try {
    locator.locate(p);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no exception)";
}

double reported_distance_mm(const std::string& message) {
  const std::string key = "nearest surface is ";
  const auto at = message.find(key);
  return at == std::string::npos ? -1.0 : std::stod(message.substr(at + key.size()));
}

TEST(PointProbe, LinearFieldIsExactAtRandomPointsOfACurvedMesh) {
  // A rod with a hemispherical end: elements on its surface are curved (edge nodes on the
  // cylinder and sphere), so finding points needs the Newton inversion of the quadratic map.
  const double radius = 5e-3, length = 30e-3;
  const TetMesh mesh = test::rod_mesh(radius, length, 2.5e-3);
  const PointLocator locator(mesh);
  const LinearField field;
  const Eigen::VectorXd nodal = field.nodal(mesh);

  std::mt19937 rng(42);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int in_cap = 0;
  for (int trial = 0; trial < 300; ++trial) {
    // Uniform in the solid, kept within 0.9 R of the axis: the quadratic surface deviates from
    // the true one by micrometres, so these points are certainly inside the mesh.
    Eigen::Vector3d p;
    do {
      p = Eigen::Vector3d(unit(rng) * (length + radius), (2 * unit(rng) - 1) * radius,
                          (2 * unit(rng) - 1) * radius);
    } while (std::hypot(std::max(p.x() - length, 0.0), std::hypot(p.y(), p.z())) > 0.9 * radius);
    in_cap += p.x() > length;
    const PointLocation at = locator.locate(p);
    EXPECT_NEAR(at.weights.sum(), 1.0, 1e-13);
    EXPECT_GE(at.reference.minCoeff(), -1e-12);
    EXPECT_LE(at.reference.sum(), 1.0 + 1e-12);
    // |u| ~ 1 and Newton stops at steps of 1e-14 in reference units: 1e-11 absolute.
    EXPECT_LT((evaluate(mesh, at, nodal) - field(p)).cwiseAbs().maxCoeff(), 1e-11)
        << "point " << p.transpose();
  }
  EXPECT_GT(in_cap, 5);  // the curved cap was sampled
}

TEST(PointProbe, PointsOnTheSurfaceAreFound) {
  const Eigen::Vector3d size(0.02, 0.01, 0.004);
  const TetMesh box = test::box_mesh(size, 0.004);
  const PointLocator box_locator(box);
  const LinearField field;
  const Eigen::VectorXd nodal = field.nodal(box);
  // A corner, an edge point and a face point of the box lie on plane faces of the mesh exactly.
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(size), Eigen::Vector3d(0.013, 0.0, 0.004),
                                   Eigen::Vector3d(0.02, 0.004, 0.001)}) {
    const PointLocation at = box_locator.locate(p);
    EXPECT_LT(at.distance, 1e-12) << p.transpose();
    EXPECT_LT((evaluate(box, at, nodal) - field(p)).cwiseAbs().maxCoeff(), 1e-11);
  }
  // Within the boundary tolerance (5 % of a ~4 mm element) a point just off a face is taken at
  // the face: 50 µm above the top.
  const PointLocation above = box_locator.locate({0.01, 0.005, 0.004 + 50e-6});
  EXPECT_NEAR(above.distance, 50e-6, 1e-12);
  EXPECT_LT((evaluate(box, above, nodal) - field({0.01, 0.005, 0.004})).cwiseAbs().maxCoeff(),
            1e-11);

  // The apex of a rounded stylus tip, on the true sphere. Whether it lies a hair inside or
  // outside the quadratic surface, it is found within the tolerance.
  const double radius = 5e-3, length = 30e-3, h = 2.5e-3;
  const TetMesh rod = test::rod_mesh(radius, length, h);
  const PointLocation apex = PointLocator(rod).locate({length + radius, 0.0, 0.0});
  EXPECT_LT(apex.distance, 0.05 * h);
}

TEST(PointProbe, PointsOutsideTheBodyAreRejectedWithTheirDistance) {
  const TetMesh box = test::box_mesh({0.02, 0.01, 0.004}, 0.004);
  const PointLocator locator(box);
  // 5 mm beyond the end face x = 20 mm.
  const std::string beyond = locate_error(locator, {0.025, 0.005, 0.002});
  EXPECT_THAT(beyond, StartsWith("point (0.025, 0.005, 0.002) m is outside the body"));
  EXPECT_NEAR(reported_distance_mm(beyond), 5.0, 1e-3);  // printed to 6 digits
  // Diagonally off the edge (20, 10, z) mm: √(5² + 5²) mm.
  EXPECT_NEAR(reported_distance_mm(locate_error(locator, {0.025, 0.015, 0.002})), std::sqrt(50.0),
              1e-3);
  // 0.5 mm above the top face: beyond the 5 % tolerance of its ~4 mm elements.
  EXPECT_NEAR(reported_distance_mm(locate_error(locator, {0.01, 0.005, 0.0045})), 0.5, 1e-3);
  // Far away from a curved surface, where the nearest point of an element is not where a
  // Gauss-Newton step from its middle would land: 15 mm beyond the apex of a rounded rod, whose
  // quadratic surface lies within micrometres of the sphere (and has a node at the apex here).
  const double radius = 5e-3, length = 30e-3;
  const TetMesh rounded = test::rod_mesh(radius, length, 2.5e-3);
  const PointLocator rod(rounded);
  EXPECT_NEAR(reported_distance_mm(locate_error(rod, {length + radius + 15e-3, 0.0, 0.0})), 15.0,
              0.01);
  // Far away, outside the search grid altogether.
  EXPECT_THAT(locate_error(locator, {1.0, 1.0, 1.0}), HasSubstr("outside the body"));
}

TEST(PointProbe, AnInvertedElementIsNamed) {
  TetMesh box = test::box_mesh({0.02, 0.01, 0.004}, 0.004);
  Tet10& t = box.tets[5];
  std::swap(t[1], t[2]);
  std::swap(t[4], t[6]);
  std::swap(t[8], t[9]);
  try {
    PointLocator locator(box);
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr("element 5 is inverted"));
  }
}

}  // namespace
}  // namespace nibrig::model::mechanics
