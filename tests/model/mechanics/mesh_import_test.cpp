#include "model/mechanics/mesh_import.hpp"

#include <gmock/gmock.h>
#include <gmsh.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <fstream>
#include <vector>

#include "model/mechanics/gmsh_session.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::mechanics {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using Triangle = std::array<std::array<double, 3>, 3>;

// A 10 × 10 × 40 (file units) box as 12 outward-facing triangles.
std::vector<Triangle> box_triangles() {
  const double v[8][3] = {{0, 0, 0},  {10, 0, 0},  {10, 10, 0},  {0, 10, 0},
                          {0, 0, 40}, {10, 0, 40}, {10, 10, 40}, {0, 10, 40}};
  const int faces[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                            {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  std::vector<Triangle> triangles;
  for (const auto& f : faces)
    triangles.push_back({{{v[f[0]][0], v[f[0]][1], v[f[0]][2]},
                          {v[f[1]][0], v[f[1]][1], v[f[1]][2]},
                          {v[f[2]][0], v[f[2]][1], v[f[2]][2]}}});
  return triangles;
}

std::filesystem::path write_stl(const std::string& name, const std::vector<Triangle>& triangles) {
  const auto file = nibrig::test::scratch_dir("mesh_import") / name;
  std::ofstream out(file);
  out << "solid test\n";
  for (const auto& t : triangles) {
    out << "facet normal 0 0 0\nouter loop\n";
    for (const auto& p : t) out << "vertex " << p[0] << " " << p[1] << " " << p[2] << "\n";
    out << "endloop\nendfacet\n";
  }
  out << "endsolid test\n";
  return file;
}

double corner_volume(const TetMesh& mesh) {
  double volume = 0;
  for (const auto& t : mesh.tets) {
    const Eigen::Vector3d a = mesh.nodes.col(t[0]), b = mesh.nodes.col(t[1]),
                          c = mesh.nodes.col(t[2]), d = mesh.nodes.col(t[3]);
    volume += (b - a).dot((c - a).cross(d - a)) / 6;
  }
  return volume;
}

TEST(MeshImport, MillimetreStlBecomesQuadraticTetsInMetres) {
  const TetMesh mesh = import_mesh_file(write_stl("box.stl", box_triangles()), {0.001, 0.003});
  ASSERT_FALSE(mesh.tets.empty());
  // Straight faces only, so the corner volume is exact up to rounding.
  EXPECT_NEAR(corner_volume(mesh), 0.01 * 0.01 * 0.04, 1e-12);
  EXPECT_NEAR(mesh.nodes.row(2).maxCoeff(), 0.040, 1e-12);
  EXPECT_EQ(mesh.region_names, std::vector<std::string>{"body"});
}

TEST(MeshImport, OpenStlNamesTheEdgeOfTheHole) {
  auto triangles = box_triangles();
  triangles.pop_back();  // one triangle of a side face missing
  EXPECT_THAT(
      [&] { import_mesh_file(write_stl("open.stl", triangles), {}); },
      ::testing::ThrowsMessage<std::runtime_error>(AllOf(
          HasSubstr("open.stl"), HasSubstr("not closed"), HasSubstr("belongs to 1 triangle"))));
}

TEST(MeshImport, NonManifoldStlIsRefused) {
  auto triangles = box_triangles();
  // A fin hanging off the bottom edge from (0,0,0) to (10,0,0): that edge then has three triangles.
  triangles.push_back({{{0, 0, 0}, {10, 0, 0}, {5, -8, -3}}});
  EXPECT_THAT([&] { import_mesh_file(write_stl("fin.stl", triangles), {}); },
              ::testing::ThrowsMessage<std::runtime_error>(AllOf(
                  HasSubstr("fin.stl"), HasSubstr("not a 2-manifold"), HasSubstr("3 triangles"))));
}

TEST(MeshImport, MshKeepsItsPhysicalGroupsAsRegionsAndNodeSets) {
  const auto file = nibrig::test::scratch_dir("mesh_import") / "rod.msh";
  {
    GmshSession session("rod");
    const int box = gmsh::model::occ::addBox(0, 0, 0, 0.05, 0.004, 0.004);
    gmsh::model::occ::synchronize();
    gmsh::vectorpair end;
    gmsh::model::getEntitiesInBoundingBox(-1e-6, -1, -1, 1e-6, 1, 1, end, 2);
    ASSERT_EQ(end.size(), 1u);
    gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, {end[0].second}), "clamp");
    gmsh::model::setPhysicalName(3, gmsh::model::addPhysicalGroup(3, {box}), "shaft");
    gmsh::option::setNumber("Mesh.MeshSizeMax", 0.002);
    gmsh::model::mesh::generate(3);  // first order on purpose: the importer raises it
    gmsh::write(file.string());
  }
  const TetMesh mesh = import_mesh_file(file, {});
  EXPECT_EQ(mesh.region_names, std::vector<std::string>{"shaft"});
  ASSERT_TRUE(mesh.node_sets.count("clamp"));
  const auto& clamp = mesh.node_sets.at("clamp");
  ASSERT_GE(clamp.size(), 9u);  // a quadratic triangulation of a square has at least 9 nodes
  for (int n : clamp) EXPECT_NEAR(mesh.nodes(0, n), 0.0, 1e-12);
  EXPECT_NEAR(corner_volume(mesh), 0.05 * 0.004 * 0.004, 1e-15);
}

TEST(MeshImport, StepSolidIsMeshed) {
  const auto file = nibrig::test::scratch_dir("mesh_import") / "pin.step";
  {
    GmshSession session("pin");
    gmsh::model::occ::addCylinder(0, 0, 0, 30, 0, 0, 2);  // millimetres, as CAD exports them
    gmsh::model::occ::synchronize();
    gmsh::write(file.string());
  }
  const TetMesh mesh = import_mesh_file(file, {0.001, 0.001});
  ASSERT_FALSE(mesh.tets.empty());
  EXPECT_NEAR(mesh.nodes.row(0).maxCoeff(), 0.030, 1e-9);
}

TEST(MeshImport, MissingUnknownAndEmptyFiles) {
  EXPECT_THAT([&] { import_mesh_file("/nonexistent/nib.stl", {}); },
              ::testing::ThrowsMessage<std::runtime_error>(
                  AllOf(HasSubstr("nib.stl"), HasSubstr("no such file"))));
  const auto obj = nibrig::test::scratch_dir("mesh_import") / "nib.obj";
  std::ofstream(obj) << "v 0 0 0\n";
  EXPECT_THAT([&] { import_mesh_file(obj, {}); }, ::testing::ThrowsMessage<std::runtime_error>(
                                                      HasSubstr("unknown mesh format '.obj'")));
  EXPECT_THAT([&] { import_mesh_file(write_stl("empty.stl", {}), {}); },
              ::testing::ThrowsMessage<std::runtime_error>(HasSubstr("empty.stl")));
}

}  // namespace
}  // namespace nibrig::model::mechanics
