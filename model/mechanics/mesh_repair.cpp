#include "model/mechanics/mesh_repair.hpp"

#include <Eigen/Geometry>
#include <array>
#include <utility>

#include "model/mechanics/tet10_element.hpp"

namespace nibrig::model::mechanics {
namespace {

// Edge node k (4..9) lies between these corners (Gmsh Tetrahedron10, tet_mesh.hpp).
constexpr std::array<std::pair<int, int>, 6> kEdgeCorners{{{0, 1}, {1, 2}, {0, 2}, {0, 3}, {2, 3}, {1, 3}}};

double corner_volume_times_six(const TetMesh& mesh, const Tet10& t) {
  const Eigen::Vector3d a = mesh.nodes.col(t[0]);
  return (mesh.nodes.col(t[1]) - a).cross(mesh.nodes.col(t[2]) - a).dot(mesh.nodes.col(t[3]) - a);
}

bool folded(const TetMesh& mesh, std::size_t e) {
  const Tet10Nodes x = tet10_nodes(mesh, e);
  double longest = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) longest = std::max(longest, (x.col(i) - x.col(j)).norm());
  // The same threshold as check_tet10: det J ≤ 1e-10 ℓ³ is degenerate.
  return tet10_min_jacobian_determinant(x) <= 1e-10 * longest * longest * longest;
}

}  // namespace

std::size_t straighten_inverted_elements(TetMesh& mesh) {
  std::size_t straightened = 0;
  for (int pass = 0; pass < 4; ++pass) {
    std::size_t this_pass = 0;
    for (std::size_t e = 0; e < mesh.tets.size(); ++e) {
      const Tet10& t = mesh.tets[e];
      if (corner_volume_times_six(mesh, t) <= 0 || !folded(mesh, e)) continue;
      for (int k = 0; k < 6; ++k) {
        const auto [a, b] = kEdgeCorners[static_cast<std::size_t>(k)];
        mesh.nodes.col(t[static_cast<std::size_t>(4 + k)]) = 0.5 * (mesh.nodes.col(t[a]) + mesh.nodes.col(t[b]));
      }
      ++this_pass;
    }
    straightened += this_pass;
    if (this_pass == 0) break;
  }
  return straightened;
}

}  // namespace nibrig::model::mechanics
