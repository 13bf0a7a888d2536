#include "model/mechanics/region_surface.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <tuple>

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

// A boundary face: corners sorted by node number (so that the two regions of an interface, and
// every face sharing an edge, compute each point from the same numbers in the same order), the edge
// nodes between them, and whether that order winds inward.
struct Face {
  std::array<int, 3> corners;  // sorted
  std::array<int, 3> edges;    // between corners (0,1) (1,2) (0,2)
  bool inward = false;
  int uses = 0;
};

// A point of the subdivided face at barycentric (i, j, k)/n of its sorted corners, named so that
// the same point of another face gets the same name: a corner by its node, an edge point by the
// edge's nodes and its step from the lower one, an inner point by the face and its steps.
using PointKey = std::tuple<int, int, int, int, int>;

PointKey point_key(const Face& f, int n, int i, int j, int k) {
  const auto& c = f.corners;
  if (i == n) return {c[0], -1, -1, 0, 0};
  if (j == n) return {c[1], -1, -1, 0, 0};
  if (k == n) return {c[2], -1, -1, 0, 0};
  if (k == 0) return {c[0], c[1], -1, j, 0};  // on edge (0,1), j steps from corner 0
  if (i == 0) return {c[1], c[2], -1, k, 0};
  if (j == 0) return {c[0], c[2], -1, k, 0};
  return {c[0], c[1], c[2], j, k};
}

// The quadratic triangle's map (6-node shape functions) at barycentric (l0, l1, l2).
Eigen::Vector3d on_face(const TetMesh& mesh, const Face& f, double l0, double l1, double l2) {
  const auto x = [&](int node) { return Eigen::Vector3d(mesh.nodes.col(node)); };
  return l0 * (2 * l0 - 1) * x(f.corners[0]) + l1 * (2 * l1 - 1) * x(f.corners[1]) +
         l2 * (2 * l2 - 1) * x(f.corners[2]) + 4 * l0 * l1 * x(f.edges[0]) + 4 * l1 * l2 * x(f.edges[1]) +
         4 * l0 * l2 * x(f.edges[2]);
}

}  // namespace

std::vector<io::SurfaceMesh> region_surfaces(const TetMesh& mesh, int subdivisions) {
  if (mesh.tets.empty()) throw std::invalid_argument("region surfaces: the mesh has no tetrahedra");
  if (subdivisions < 1) throw std::invalid_argument("region surfaces: subdivisions must be 1 or more");
  const int n = subdivisions;
  std::vector<io::SurfaceMesh> out;
  for (std::size_t r = 0; r < mesh.region_names.size(); ++r) {
    // Faces of the region's tets by their sorted corners: a face used once bounds the region.
    std::map<std::array<int, 3>, Face> faces;
    for (std::size_t e = 0; e < mesh.tets.size(); ++e) {
      if (static_cast<std::size_t>(mesh.tet_region[e]) != r) continue;
      const Tet10& t = mesh.tets[e];
      static constexpr int kFaces[4][4] = {{0, 1, 2, 3}, {0, 1, 3, 2}, {0, 2, 3, 1}, {1, 2, 3, 0}};
      for (const auto& local : kFaces) {
        std::array<int, 3> l{local[0], local[1], local[2]};
        std::sort(l.begin(), l.end(), [&](int a, int b) { return t[a] < t[b]; });
        Face face{{t[l[0]], t[l[1]], t[l[2]]},
                  {edge_node(t, l[0], l[1]), edge_node(t, l[1], l[2]), edge_node(t, l[0], l[2])}};
        const Eigen::Vector3d a = mesh.nodes.col(face.corners[0]), b = mesh.nodes.col(face.corners[1]),
                              c = mesh.nodes.col(face.corners[2]), d = mesh.nodes.col(t[local[3]]);
        face.inward = (b - a).cross(c - a).dot(d - a) > 0;  // the normal points at the fourth corner
        auto [it, inserted] = faces.emplace(face.corners, face);
        ++it->second.uses;
      }
    }
    if (faces.empty())
      throw std::invalid_argument("region surfaces: region '" + mesh.region_names[r] + "' has no tetrahedra");
    io::SurfaceMesh surface;
    surface.name = mesh.region_names[r];
    std::map<PointKey, std::uint32_t> index;
    for (const auto& entry : faces) {
      const Face& f = entry.second;
      if (f.uses != 1) continue;
      const auto point = [&](int i, int j) {
        const int k = n - i - j;
        auto [it, inserted] = index.emplace(point_key(f, n, i, j, k), static_cast<std::uint32_t>(surface.vertices.size()));
        if (inserted) {
          const Eigen::Vector3d x = on_face(mesh, f, double(i) / n, double(j) / n, double(k) / n);
          surface.vertices.push_back({x.x(), x.y(), x.z()});
        }
        return it->second;
      };
      const auto triangle = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        surface.triangles.push_back(f.inward ? std::array<std::uint32_t, 3>{a, c, b} : std::array<std::uint32_t, 3>{a, b, c});
      };
      // i steps toward corner 0, j toward corner 1: rows of small triangles across the face.
      for (int i = 0; i < n; ++i)
        for (int j = 0; i + j < n; ++j) {
          triangle(point(i + 1, j), point(i, j + 1), point(i, j));
          if (i + j + 2 <= n) triangle(point(i + 1, j), point(i + 1, j + 1), point(i, j + 1));
        }
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
