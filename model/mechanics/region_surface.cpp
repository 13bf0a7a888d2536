#include "model/mechanics/region_surface.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <unordered_map>

namespace nibrig::model::mechanics {
namespace {

// Gmsh's Tetrahedron10: the edge node between corners i and j.
int edge_node(const Tet10& t, int i, int j) {
  const int a = std::min(i, j), b = std::max(i, j);
  if (a == 0 && b == 1) return t[4];
  if (a == 1 && b == 2) return t[5];
  if (a == 0 && b == 2) return t[6];
  if (a == 0 && b == 3) return t[7];
  if (a == 2 && b == 3) return t[8];
  return t[9];  // (1, 3)
}

struct Face {
  std::array<int, 3> corners;  // wound outward from the tet
  std::array<int, 3> edges;    // edge nodes (c0,c1) (c1,c2) (c2,c0)
  int uses = 0;
};

}  // namespace

std::vector<io::SurfaceMesh> region_surfaces(const TetMesh& mesh) {
  if (mesh.tets.empty()) throw std::invalid_argument("region surfaces: the mesh has no tetrahedra");
  std::vector<io::SurfaceMesh> out;
  for (std::size_t r = 0; r < mesh.region_names.size(); ++r) {
    // Faces of the region's tets by their sorted corners: a face used once bounds the region.
    std::map<std::array<int, 3>, Face> faces;
    for (std::size_t e = 0; e < mesh.tets.size(); ++e) {
      if (static_cast<std::size_t>(mesh.tet_region[e]) != r) continue;
      const Tet10& t = mesh.tets[e];
      static constexpr int kFaces[4][4] = {{0, 1, 2, 3}, {0, 1, 3, 2}, {0, 2, 3, 1}, {1, 2, 3, 0}};
      for (const auto& f : kFaces) {
        Face face{{t[f[0]], t[f[1]], t[f[2]]}, {edge_node(t, f[0], f[1]), edge_node(t, f[1], f[2]),
                                                edge_node(t, f[2], f[0])}, 1};
        // Outward: the normal points away from the fourth corner.
        const Eigen::Vector3d a = mesh.nodes.col(face.corners[0]), b = mesh.nodes.col(face.corners[1]),
                              c = mesh.nodes.col(face.corners[2]), d = mesh.nodes.col(t[f[3]]);
        if ((b - a).cross(c - a).dot(d - a) > 0) {
          std::swap(face.corners[1], face.corners[2]);
          face.edges = {face.edges[2], face.edges[1], face.edges[0]};
        }
        auto key = face.corners;
        std::sort(key.begin(), key.end());
        auto [it, inserted] = faces.emplace(key, face);
        if (!inserted) ++it->second.uses;
      }
    }
    if (faces.empty())
      throw std::invalid_argument("region surfaces: region '" + mesh.region_names[r] + "' has no tetrahedra");
    io::SurfaceMesh surface;
    surface.name = mesh.region_names[r];
    std::unordered_map<int, std::uint32_t> index;
    const auto vertex = [&](int node) {
      auto [it, inserted] = index.emplace(node, static_cast<std::uint32_t>(surface.vertices.size()));
      if (inserted) surface.vertices.push_back({mesh.nodes(0, node), mesh.nodes(1, node), mesh.nodes(2, node)});
      return it->second;
    };
    for (const auto& [key, f] : faces) {
      if (f.uses != 1) continue;
      const auto c0 = vertex(f.corners[0]), c1 = vertex(f.corners[1]), c2 = vertex(f.corners[2]);
      const auto m01 = vertex(f.edges[0]), m12 = vertex(f.edges[1]), m20 = vertex(f.edges[2]);
      surface.triangles.push_back({c0, m01, m20});
      surface.triangles.push_back({m01, c1, m12});
      surface.triangles.push_back({m20, m12, c2});
      surface.triangles.push_back({m01, m12, m20});
    }
    out.push_back(std::move(surface));
  }
  return out;
}

double enclosed_volume(const io::SurfaceMesh& surface) {
  double six_v = 0.0;
  for (const auto& t : surface.triangles) {
    const auto& a = surface.vertices[t[0]];
    const auto& b = surface.vertices[t[1]];
    const auto& c = surface.vertices[t[2]];
    six_v += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
  }
  return six_v / 6.0;
}

}  // namespace nibrig::model::mechanics
