// Volume of a mesh's tetrahedra from their corner nodes: exact for straight-sided elements; on
// curved faces the chords cut a sliver whose relative size shrinks with the element size (below
// 0.5 % at the sizes the tests use). region -1: every tetrahedron.
#pragma once

#include <Eigen/Geometry>

#include "model/mechanics/tet_mesh.hpp"

namespace nibrig::model::mechanics::testing {

inline double corner_volume(const TetMesh& mesh, int region = -1) {
  double volume = 0;
  for (std::size_t e = 0; e < mesh.tets.size(); ++e) {
    if (region >= 0 && mesh.tet_region[e] != region) continue;
    const auto& t = mesh.tets[e];
    const Eigen::Vector3d a = mesh.nodes.col(t[0]);
    volume += (mesh.nodes.col(t[1]) - a).cross(mesh.nodes.col(t[2]) - a).dot(mesh.nodes.col(t[3]) - a) / 6;
  }
  return volume;
}

}  // namespace nibrig::model::mechanics::testing
