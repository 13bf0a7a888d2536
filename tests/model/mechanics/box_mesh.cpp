#include "tests/model/mechanics/box_mesh.hpp"

#include <gmsh.h>

#include "model/mechanics/gmsh_session.hpp"
#include "model/mechanics/shape_builders.hpp"

namespace nibrig::model::mechanics::test {
namespace {

// Uniform elements (no refinement by curvature: the minimum size is the maximum), clamp on x = 0.
TetMesh mesh_current_model(double mesh_size) {
  generate_quadratic_tets(mesh_size, mesh_size);
  TetMesh mesh = tet_mesh_from_gmsh("body");
  mesh.node_sets["clamp"] = nodes_in_box(mesh, {-1, -1, -1}, {0, 1, 1});
  return mesh;
}

}  // namespace

TetMesh box_mesh(const Eigen::Vector3d& size, double mesh_size) {
  GmshSession session("box");
  gmsh::model::occ::addBox(0.0, 0.0, 0.0, size.x(), size.y(), size.z());
  gmsh::model::occ::synchronize();
  return mesh_current_model(mesh_size);
}

TetMesh rod_mesh(double radius, double length, double mesh_size) {
  GmshSession session("rod");
  const int cylinder = gmsh::model::occ::addCylinder(0.0, 0.0, 0.0, length, 0.0, 0.0, radius);
  const int ball = gmsh::model::occ::addSphere(length, 0.0, 0.0, radius);
  gmsh::vectorpair fused;
  std::vector<gmsh::vectorpair> map;
  // The ball's half inside the cylinder merges away, leaving the hemispherical end.
  gmsh::model::occ::fuse({{3, cylinder}}, {{3, ball}}, fused, map);
  gmsh::model::occ::synchronize();
  return mesh_current_model(mesh_size);
}

}  // namespace nibrig::model::mechanics::test
