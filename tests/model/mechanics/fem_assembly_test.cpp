#include "model/mechanics/fem_assembly.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <stdexcept>

#include "model/mechanics/tet10_element.hpp"
#include "tests/model/mechanics/box_mesh.hpp"

namespace nibrig::model::mechanics {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

const IsotropicMaterial kVero{"VeroClear", 0.45e9, 0.35, 1180.0};

std::string assembly_error(const TetMesh& mesh, const std::vector<IsotropicMaterial>& materials,
                           const std::vector<std::string>& held) {
  try {
    assemble(mesh, materials, held);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no exception)";
}

TEST(FemAssembly, FreeBoxHasExactlySixRigidBodyModesAndItsMass) {
  const Eigen::Vector3d size(0.03, 0.01, 0.006);
  const TetMesh mesh = test::box_mesh(size, 0.008);
  const FemSystem sys = assemble(mesh, {kVero}, {});
  ASSERT_EQ(sys.free_dofs(), 3 * mesh.nodes.cols());
  ASSERT_LT(sys.free_dofs(), 1500) << "keep the dense solve small";

  // Total mass: a uniform x-translation t has tᵀ M t = ρV, exact on straight elements.
  Eigen::VectorXd t = Eigen::VectorXd::Zero(sys.free_dofs());
  for (Eigen::Index n = 0; n < mesh.nodes.cols(); ++n) t(3 * n) = 1.0;
  const double mass = kVero.density * size.prod();
  EXPECT_NEAR(t.dot(sys.mass * t), mass, 1e-12 * mass);

  const Eigen::MatrixXd k(sys.stiffness), m(sys.mass);
  EXPECT_LT((k - k.transpose()).cwiseAbs().maxCoeff(), 1e-12 * k.cwiseAbs().maxCoeff());
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(k, m);
  ASSERT_EQ(dense.info(), Eigen::Success);
  const Eigen::VectorXd& lambda = dense.eigenvalues();
  // The rigid motions are exactly in the null space of K, so their computed eigenvalues are
  // round-off of the dense solver, ~1e-16 of the largest (~5e12 rad²/s² here), i.e. ~1e-3, while
  // the first elastic mode of this box (free-free bending across its 6 mm, a few kHz) is ~6e8.
  // A threshold of 1e-6 of the seventh eigenvalue separates the two by five orders of magnitude
  // on both sides.
  const double threshold = 1e-6 * lambda(6);
  for (int i = 0; i < 6; ++i) EXPECT_LT(std::abs(lambda(i)), threshold) << "mode " << i;
  EXPECT_GT(lambda(6), threshold);
  // Euler-Bernoulli puts that mode at 4.2 kHz (ω² = 7e8); shear makes this short, thick beam softer.
  EXPECT_GT(lambda(6), 1e8);
}

TEST(FemAssembly, LinearDisplacementIsAnExactPatchOnAMesh) {
  const Eigen::Vector3d size(0.02, 0.01, 0.008);
  const TetMesh mesh = test::box_mesh(size, 0.004);
  const IsotropicMaterial mat{"patch", 2.0e9, 0.3, 1000.0};
  const FemSystem sys = assemble(mesh, {mat}, {});
  Eigen::Matrix3d g;
  g << 1.0, 0.4, -0.3, 0.2, -0.6, 0.5, -0.1, 0.3, 0.7;
  g *= 1e-3;
  Eigen::VectorXd u(sys.free_dofs());
  for (Eigen::Index n = 0; n < mesh.nodes.cols(); ++n) u.segment<3>(3 * n) = g * mesh.nodes.col(n);
  // Strain energy of the uniform strain ε = sym(G): ½ ε:C:ε V, with ε:C:ε = λ (tr ε)² + 2μ ε:ε.
  const Eigen::Matrix3d eps = 0.5 * (g + g.transpose());
  const LameParameters l = lame_parameters(mat);
  const double exact =
      0.5 * (l.lambda * eps.trace() * eps.trace() + 2 * l.mu * eps.squaredNorm()) * size.prod();
  const Eigen::VectorXd f = sys.stiffness * u;
  EXPECT_NEAR(0.5 * u.dot(f), exact, 1e-10 * exact);
  // Interior nodes are in equilibrium (uniform stress has no divergence): their forces are
  // round-off against the boundary nodes' tractions.
  const double scale = f.cwiseAbs().maxCoeff();
  int interior = 0;
  for (Eigen::Index n = 0; n < mesh.nodes.cols(); ++n) {
    const Eigen::Vector3d p = mesh.nodes.col(n);
    const double margin = 1e-9;
    if ((p.array() > margin).all() && (p.array() < size.array() - margin).all()) {
      ++interior;
      EXPECT_LT(f.segment<3>(3 * n).cwiseAbs().maxCoeff(), 1e-10 * scale) << "node " << n;
    }
  }
  EXPECT_GT(interior, 10);
}

TEST(FemAssembly, ClampedSystemIsTheFreeRowsAndColumnsOfTheFullOne) {
  const TetMesh mesh = test::box_mesh({0.03, 0.01, 0.004}, 0.005);
  const FemSystem full = assemble(mesh, {kVero}, {});
  const FemSystem held = assemble(mesh, {kVero}, {"clamp"});
  const auto clamped = static_cast<Eigen::Index>(mesh.node_sets.at("clamp").size());
  ASSERT_GT(clamped, 3);
  EXPECT_EQ(held.free_dofs(), full.free_dofs() - 3 * clamped);
  for (int n : mesh.node_sets.at("clamp"))
    for (int c = 0; c < 3; ++c) EXPECT_EQ(held.full_to_free[3 * n + c], -1);

  const Eigen::MatrixXd kf(full.stiffness), mf(full.mass), kh(held.stiffness), mh(held.mass);
  Eigen::MatrixXd k_sub(held.free_dofs(), held.free_dofs()), m_sub = k_sub;
  for (Eigen::Index i = 0; i < held.free_dofs(); ++i)
    for (Eigen::Index j = 0; j < held.free_dofs(); ++j) {
      k_sub(i, j) = kf(held.free_to_full[i], held.free_to_full[j]);
      m_sub(i, j) = mf(held.free_to_full[i], held.free_to_full[j]);
    }
  // Same element matrices summed in the same order: equal up to round-off.
  EXPECT_LT((kh - k_sub).cwiseAbs().maxCoeff(), 1e-12 * kf.cwiseAbs().maxCoeff());
  EXPECT_LT((mh - m_sub).cwiseAbs().maxCoeff(), 1e-12 * mf.cwiseAbs().maxCoeff());

  // expand puts free values back at their DOFs and zeros at the clamp.
  const Eigen::VectorXd v = Eigen::VectorXd::LinSpaced(held.free_dofs(), 1.0, 2.0);
  const Eigen::VectorXd e = held.expand(v);
  for (Eigen::Index d = 0; d < held.full_dofs(); ++d) {
    const int f = held.full_to_free[d];
    EXPECT_EQ(e(d), f < 0 ? 0.0 : v(f));
  }
}

TEST(FemAssembly, BadInputIsRejectedWithAClearMessage) {
  const TetMesh mesh = test::box_mesh({0.02, 0.01, 0.004}, 0.005);

  TetMesh no_clamp = mesh;
  no_clamp.node_sets["clamp"].clear();
  EXPECT_EQ(assembly_error(no_clamp, {kVero}, {"clamp"}),
            "the mesh has no clamped region: node set 'clamp' is empty");
  EXPECT_THAT(assembly_error(mesh, {kVero}, {"grip"}), HasSubstr("no node set 'grip'"));

  IsotropicMaterial negative = kVero;
  negative.youngs_modulus = -1e9;
  EXPECT_THAT(assembly_error(mesh, {negative}, {"clamp"}),
              AllOf(HasSubstr("material 'VeroClear'"), HasSubstr("Young's modulus")));

  TetMesh two_regions = mesh;
  two_regions.region_names = {"body", "tip"};
  two_regions.tet_region.back() = 1;
  EXPECT_THAT(assembly_error(two_regions, {kVero}, {"clamp"}),
              HasSubstr("region 'tip' has no material"));
  EXPECT_NO_THROW(assemble(two_regions, {kVero, {"tip", 0.1e9, 0.45, 1100.0}}, {"clamp"}));

  // Swapping corners 1 and 2 (and with them the edge nodes (0,1)↔(0,2) and (1,3)↔(2,3)) mirrors
  // the reference element: the tetrahedron is inside out.
  TetMesh inverted = mesh;
  const std::size_t bad = inverted.tets.size() / 2;
  Tet10& t = inverted.tets[bad];
  std::swap(t[1], t[2]);
  std::swap(t[4], t[6]);
  std::swap(t[8], t[9]);
  EXPECT_THAT(assembly_error(inverted, {kVero}, {"clamp"}),
              AllOf(HasSubstr("element " + std::to_string(bad)), HasSubstr("inverted")));

  TetMesh out_of_range = mesh;
  out_of_range.tets[0][3] = static_cast<int>(mesh.nodes.cols());
  EXPECT_THAT(assembly_error(out_of_range, {kVero}, {"clamp"}), HasSubstr("element 0 refers to"));

  TetMesh orphan = mesh;
  orphan.nodes.conservativeResize(3, mesh.nodes.cols() + 1);
  orphan.nodes.col(mesh.nodes.cols()).setZero();
  EXPECT_THAT(assembly_error(orphan, {kVero}, {"clamp"}), HasSubstr("belongs to no element"));

  TetMesh all_held = mesh;
  all_held.node_sets["all"].resize(static_cast<std::size_t>(mesh.nodes.cols()));
  for (Eigen::Index n = 0; n < mesh.nodes.cols(); ++n)
    all_held.node_sets["all"][static_cast<std::size_t>(n)] = static_cast<int>(n);
  EXPECT_THAT(assembly_error(all_held, {kVero}, {"all"}), HasSubstr("every node"));
}

}  // namespace
}  // namespace nibrig::model::mechanics
