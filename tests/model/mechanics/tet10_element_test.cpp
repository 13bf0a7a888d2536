#include "model/mechanics/tet10_element.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <random>
#include <stdexcept>

namespace nibrig::model::mechanics {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }

// Reference-element node coordinates in Gmsh's Tetrahedron10 order, written out here from the
// Gmsh documentation rather than taken from the code under test.
const std::array<Eigen::Vector3d, 10> kReferenceNodes{
    Eigen::Vector3d(0, 0, 0),    Eigen::Vector3d(1, 0, 0),   Eigen::Vector3d(0, 1, 0),
    Eigen::Vector3d(0, 0, 1),    Eigen::Vector3d(0.5, 0, 0), Eigen::Vector3d(0.5, 0.5, 0),
    Eigen::Vector3d(0, 0.5, 0),  Eigen::Vector3d(0, 0, 0.5), Eigen::Vector3d(0, 0.5, 0.5),
    Eigen::Vector3d(0.5, 0, 0.5)};

// A straight (affine) element: edge nodes at the midpoints of the corners given.
Tet10Nodes straight(const std::array<Eigen::Vector3d, 4>& c) {
  Tet10Nodes x;
  for (int a = 0; a < 10; ++a) {
    const Eigen::Vector3d& r = kReferenceNodes[a];
    x.col(a) = c[0] + r.x() * (c[1] - c[0]) + r.y() * (c[2] - c[0]) + r.z() * (c[3] - c[0]);
  }
  return x;
}

Tet10Nodes random_straight(std::mt19937& rng) {
  std::uniform_real_distribution<double> jitter(-0.2e-3, 0.2e-3);
  const auto j = [&] { return Eigen::Vector3d(jitter(rng), jitter(rng), jitter(rng)); };
  // A well-shaped tetrahedron of ~2 mm edges, jittered so that nothing is axis-aligned.
  return straight({Eigen::Vector3d(0, 0, 0) + j(), Eigen::Vector3d(2e-3, 0, 0) + j(),
                   Eigen::Vector3d(0.5e-3, 1.8e-3, 0) + j(),
                   Eigen::Vector3d(0.7e-3, 0.6e-3, 1.9e-3) + j()});
}

// Moves the edge nodes off the chords by up to 5 % of the edge length: a curved element like
// those on a meshed cylinder.
Tet10Nodes random_curved(std::mt19937& rng) {
  Tet10Nodes x = random_straight(rng);
  std::uniform_real_distribution<double> bend(-0.1e-3, 0.1e-3);
  for (int a = 4; a < 10; ++a) x.col(a) += Eigen::Vector3d(bend(rng), bend(rng), bend(rng));
  return x;
}

double straight_volume(const Tet10Nodes& x) {
  Eigen::Matrix3d m;
  m << x.col(1) - x.col(0), x.col(2) - x.col(0), x.col(3) - x.col(0);
  return m.determinant() / 6.0;
}

// Isotropic elasticity in Voigt order (xx, yy, zz, yz, xz, xy) with engineering shear strains,
// from E and ν directly (not through the code's Lamé parameters).
Eigen::Matrix<double, 6, 6> voigt_elasticity(double e, double nu) {
  Eigen::Matrix<double, 6, 6> c = Eigen::Matrix<double, 6, 6>::Zero();
  const double f = e / ((1 + nu) * (1 - 2 * nu));
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) c(i, j) = f * (i == j ? 1 - nu : nu);
    c(3 + i, 3 + i) = f * (1 - 2 * nu) / 2;
  }
  return c;
}

Eigen::Matrix<double, 6, 1> voigt(const Eigen::Matrix3d& strain) {
  Eigen::Matrix<double, 6, 1> v;
  v << strain(0, 0), strain(1, 1), strain(2, 2), 2 * strain(1, 2), 2 * strain(0, 2),
      2 * strain(0, 1);
  return v;
}

Eigen::Matrix<double, 30, 1> nodal(const Tet10Nodes& x, const auto& field) {
  Eigen::Matrix<double, 30, 1> u;
  for (int a = 0; a < 10; ++a) u.segment<3>(3 * a) = field(Eigen::Vector3d(x.col(a)));
  return u;
}

TEST(TetQuadrature, RulesIntegrateEveryMonomialUpToTheirDegree) {
  // ∫ ξ1^i ξ2^j ξ3^k over the reference tetrahedron = i! j! k! / (i + j + k + 3)!. Each rule sums
  // at most 14 positive terms of size ≤ 1/6, so round-off stays below 1e-15.
  for (const TetQuadrature* rule : {&tet_quadrature_degree2(), &tet_quadrature_degree5()}) {
    for (int i = 0; i <= rule->degree; ++i)
      for (int j = 0; i + j <= rule->degree; ++j)
        for (int k = 0; i + j + k <= rule->degree; ++k) {
          double sum = 0.0;
          for (std::size_t q = 0; q < rule->points.size(); ++q) {
            const Eigen::Vector3d& p = rule->points[q];
            sum += rule->weights[q] * std::pow(p.x(), i) * std::pow(p.y(), j) * std::pow(p.z(), k);
          }
          EXPECT_NEAR(sum, factorial(i) * factorial(j) * factorial(k) / factorial(i + j + k + 3),
                      1e-15)
              << "degree " << rule->degree << " rule, monomial " << i << j << k;
        }
    for (double w : rule->weights) EXPECT_GT(w, 0.0);
  }
  EXPECT_EQ(tet_quadrature_degree2().points.size(), 4u);
  EXPECT_EQ(tet_quadrature_degree5().points.size(), 14u);
}

TEST(Tet10Shape, InterpolatesNodesSumsToOneAndGradientsMatchDifferences) {
  // Kronecker property at the nodes (exact arithmetic on halves and quarters: tolerance 1e-15).
  for (int b = 0; b < 10; ++b) {
    const Tet10Shape n = tet10_shape(kReferenceNodes[b]);
    for (int a = 0; a < 10; ++a) EXPECT_NEAR(n(a), a == b ? 1.0 : 0.0, 1e-15) << a << " at " << b;
  }
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    Eigen::Vector3d xi(u(rng), u(rng), u(rng));
    xi *= u(rng) / xi.sum();  // inside the reference tetrahedron
    EXPECT_NEAR(tet10_shape(xi).sum(), 1.0, 1e-14);
    const Tet10ShapeGradient g = tet10_shape_gradient(xi);
    EXPECT_LT(g.colwise().sum().cwiseAbs().maxCoeff(), 1e-13);
    // Central differences of a quadratic are exact up to round-off ~ 1e-16 / h = 1e-10.
    const double h = 1e-6;
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d e = Eigen::Vector3d::Unit(k) * h;
      const Tet10Shape fd = (tet10_shape(xi + e) - tet10_shape(xi - e)) / (2 * h);
      EXPECT_LT((fd - g.col(k)).cwiseAbs().maxCoeff(), 1e-9) << "direction " << k;
    }
  }
}

TEST(Tet10Shape, ReproducesQuadraticFieldsOnAStraightElement) {
  std::mt19937 rng(11);
  const Tet10Nodes x = random_straight(rng);
  // Any quadratic in x lies in the P2 space of an affine element; values are O(1) and the
  // interpolation sums 10 of them: round-off ~ 1e-15.
  const auto f = [](const Eigen::Vector3d& p) {
    const Eigen::Vector3d s = p * 1e3;  // mm, so that the terms are O(1)
    return 0.3 + s.x() - 2 * s.y() + 0.5 * s.z() + s.x() * s.y() - 0.7 * s.z() * s.z();
  };
  Tet10Shape values;
  for (int a = 0; a < 10; ++a) values(a) = f(x.col(a));
  std::uniform_real_distribution<double> u(0.0, 0.33);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Vector3d xi(u(rng), u(rng), u(rng));
    EXPECT_NEAR(tet10_shape(xi).dot(values), f(tet10_position(x, xi)), 1e-12);
  }
}

TEST(Tet10Mass, StraightElementMatchesTheClosedFormAndTotalMass) {
  std::mt19937 rng(3);
  const Tet10Nodes x = random_straight(rng);
  const double rho = 1180.0, v = straight_volume(x);
  // Closed-form consistent mass of the straight P2 tetrahedron, ρV/420 times: corner-corner 6 on
  // the diagonal and 1 off it; corner-edge −4 if the edge touches the corner, −6 if not; edge-edge
  // 32 on the diagonal, 16 for edges sharing a corner, 8 for opposite edges (from ∫ L^a = a! 3! V /
  // (Σa + 3)!, e.g. ∫ (L(2L−1))² = 6V/420).
  const std::array<std::array<int, 2>, 6> edges{{{0, 1}, {1, 2}, {0, 2}, {0, 3}, {2, 3}, {1, 3}}};
  const auto touches = [&](int e, int c) { return edges[e][0] == c || edges[e][1] == c; };
  Tet10ScalarMatrix expected;
  for (int a = 0; a < 10; ++a)
    for (int b = 0; b < 10; ++b) {
      double m;
      if (a < 4 && b < 4) {
        m = a == b ? 6 : 1;
      } else if (a >= 4 && b >= 4) {
        const int ea = a - 4, eb = b - 4;
        const bool share = touches(eb, edges[ea][0]) || touches(eb, edges[ea][1]);
        m = a == b ? 32 : (share ? 16 : 8);
      } else {
        const int corner = a < 4 ? a : b, edge = (a < 4 ? b : a) - 4;
        m = touches(edge, corner) ? -4 : -6;
      }
      expected(a, b) = rho * v / 420.0 * m;
    }
  const Tet10ScalarMatrix m = tet10_scalar_mass(x, rho);
  // The degree-5 rule is exact for this degree-4 integrand: only round-off (entries ~ ρV).
  EXPECT_LT((m - expected).cwiseAbs().maxCoeff(), 1e-13 * rho * v);
  const Tet10Matrix full = tet10_mass(x, rho);
  EXPECT_NEAR(full.sum(), 3 * rho * v, 1e-13 * rho * v);  // each component carries ρV
  EXPECT_NEAR(tet10_scalar_mass(x, 1.0).sum(), v, 1e-13 * v);
}

TEST(Tet10Stiffness, RigidMotionsCostNoForceOnStraightAndCurvedElements) {
  std::mt19937 rng(5);
  const LameParameters lame = lame_parameters({"test", 0.45e9, 0.35, 1180.0});
  for (const Tet10Nodes& x : {random_straight(rng), random_curved(rng)}) {
    const Tet10Matrix k = tet10_stiffness(x, lame);
    EXPECT_LT((k - k.transpose()).cwiseAbs().maxCoeff(), 1e-12 * k.cwiseAbs().maxCoeff());
    // Isoparametric elements reproduce linear fields exactly, so a rigid motion has zero strain
    // at every quadrature point; what remains is round-off of 30-term sums, < 1e-13 relative.
    for (int d = 0; d < 3; ++d) {
      const auto translation = [d](const Eigen::Vector3d&) {
        return Eigen::Vector3d(Eigen::Vector3d::Unit(d) * 1e-3);
      };
      const auto rotation = [d](const Eigen::Vector3d& p) {
        return Eigen::Vector3d(Eigen::Vector3d::Unit(d).cross(p) * 1e-2);
      };
      for (const Eigen::Matrix<double, 30, 1>& u : {nodal(x, translation), nodal(x, rotation)}) {
        const double scale = k.cwiseAbs().maxCoeff() * u.cwiseAbs().maxCoeff();
        EXPECT_LT((k * u).cwiseAbs().maxCoeff(), 1e-12 * scale) << "axis " << d;
      }
    }
  }
}

TEST(Tet10Stiffness, PatchTestsLinearAndQuadraticDisplacements) {
  std::mt19937 rng(9);
  const double e = 2.1e9, nu = 0.3;
  const Tet10Nodes x = random_straight(rng);
  const Tet10Matrix k = tet10_stiffness(x, lame_parameters({"test", e, nu, 1000.0}));
  const Eigen::Matrix<double, 6, 6> c = voigt_elasticity(e, nu);

  // Uniform strain: u = G x with G arbitrary (its skew part is a rotation and costs nothing).
  Eigen::Matrix3d g;
  g << 1.0, 0.3, -0.2, 0.1, -0.5, 0.4, 0.25, -0.3, 0.8;
  g *= 1e-3;
  const auto linear = [&g](const Eigen::Vector3d& p) { return Eigen::Vector3d(g * p); };
  const Eigen::Matrix<double, 6, 1> eps = voigt(0.5 * (g + g.transpose()));
  const double exact = 0.5 * eps.dot(c * eps) * straight_volume(x);
  const Eigen::Matrix<double, 30, 1> u = nodal(x, linear);
  EXPECT_NEAR(0.5 * u.dot(k * u), exact, 1e-12 * exact);

  // Linearly varying strain (quadratic displacement, as in bending) is still in the P2 space of a
  // straight element and the degree-2 rule integrates its quadratic energy density exactly. The
  // reference integrates ½ ε:C:ε with the degree-5 rule mapped affinely onto the element; that rule
  // is verified above on monomials.
  const Eigen::Vector3d x0 = x.col(0);
  const auto quadratic = [&](const Eigen::Vector3d& p) {
    const Eigen::Vector3d s = (p - x0) * 1e3;  // mm
    return Eigen::Vector3d(1e-6 * Eigen::Vector3d(s.x() * s.y(), -0.5 * s.z() * s.z() + s.x(),
                                                  0.3 * s.x() * s.x() - s.y() * s.z()));
  };
  const auto strain = [&](const Eigen::Vector3d& p) {
    const Eigen::Vector3d s = (p - x0) * 1e3;
    Eigen::Matrix3d grad;  // ∂u_i/∂x_j, the 1e-6 m per mm² field differentiated in metres
    grad << s.y(), s.x(), 0.0, 1.0, 0.0, -s.z(), 0.6 * s.x(), -s.z(), -s.y();
    grad *= 1e-3;
    return voigt(0.5 * (grad + grad.transpose()));
  };
  double reference = 0.0;
  const TetQuadrature& rule = tet_quadrature_degree5();
  for (std::size_t q = 0; q < rule.points.size(); ++q) {
    const Eigen::Vector3d& r = rule.points[q];
    const Eigen::Vector3d p =
        x0 + r.x() * (x.col(1) - x0) + r.y() * (x.col(2) - x0) + r.z() * (x.col(3) - x0);
    const Eigen::Matrix<double, 6, 1> s = strain(p);
    reference += rule.weights[q] * 6.0 * straight_volume(x) * 0.5 * s.dot(c * s);
  }
  const Eigen::Matrix<double, 30, 1> w = nodal(x, quadratic);
  EXPECT_NEAR(0.5 * w.dot(k * w), reference, 1e-11 * reference);
}

TEST(Tet10Check, InvertedAndCollapsedElementsAreNamed) {
  std::mt19937 rng(1);
  Tet10Nodes x = random_straight(rng);
  EXPECT_NO_THROW(check_tet10(x, 3));
  EXPECT_GT(tet10_min_jacobian_determinant(x), 0.0);

  // Mirroring the element through a plane inverts it.
  Tet10Nodes mirrored = x;
  mirrored.row(2) *= -1.0;
  try {
    check_tet10(mirrored, 17);
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(std::string(e.what()), AllOf(HasSubstr("element 17"), HasSubstr("inverted")));
  }
  EXPECT_THROW(tet10_stiffness(mirrored, {1e9, 1e9}), std::invalid_argument);

  // All corners in one plane: zero volume.
  Tet10Nodes flat = x;
  flat.row(2).setConstant(0.0);
  try {
    check_tet10(flat, 4);
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr("element 4"));
  }

  // An edge node pulled across the element folds it although the corners are fine.
  Tet10Nodes folded = x;
  folded.col(4) = x.col(2) + 0.3 * (x.col(2) - x.col(4));
  EXPECT_THROW(check_tet10(folded, 0), std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::model::mechanics
