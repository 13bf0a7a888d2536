#include "tests/model/mechanics/box_mesh.hpp"

#include "tests/support/gmsh_tet_mesh.hpp"

namespace nibrig::model::mechanics::test {

TetMesh box_mesh(const Eigen::Vector3d& size, double mesh_size) {
  nibrig::test::GmshSession session;
  gmsh::model::add("box");
  gmsh::model::occ::addBox(0.0, 0.0, 0.0, size.x(), size.y(), size.z());
  gmsh::model::occ::synchronize();
  nibrig::test::generate_quadratic_tets(mesh_size);
  return nibrig::test::tet_mesh_from_gmsh();
}

TetMesh rod_mesh(double radius, double length, double mesh_size) {
  nibrig::test::GmshSession session;
  gmsh::model::add("rod");
  const int cylinder = gmsh::model::occ::addCylinder(0.0, 0.0, 0.0, length, 0.0, 0.0, radius);
  const int ball = gmsh::model::occ::addSphere(length, 0.0, 0.0, radius);
  gmsh::vectorpair fused;
  std::vector<gmsh::vectorpair> map;
  // The ball's half inside the cylinder merges away, leaving the hemispherical end.
  gmsh::model::occ::fuse({{3, cylinder}}, {{3, ball}}, fused, map);
  gmsh::model::occ::synchronize();
  nibrig::test::generate_quadratic_tets(mesh_size);
  return nibrig::test::tet_mesh_from_gmsh();
}

}  // namespace nibrig::model::mechanics::test
