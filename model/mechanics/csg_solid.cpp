#include "model/mechanics/csg_solid.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <unordered_map>

#include "model/mechanics/gmsh_session.hpp"
#include "model/mechanics/region_surface.hpp"

namespace nibrig::model::mechanics {
namespace {

namespace occ = gmsh::model::occ;

// Through-holes are made a little longer than the wall they cross by the caller; below this a
// primitive is a slip of the pen, not a feature a printer could make.
constexpr double kCsgShortestLength = 1e-5;  // m

void require_csg(bool ok, const std::string& name, const std::string& what) {
  if (!ok) throw std::invalid_argument(name + ": " + what);
}

void validate_boxes(const std::vector<CsgBox>& boxes, const std::string& name, const char* list) {
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const Eigen::Vector3d size = boxes[i].hi - boxes[i].lo;
    require_csg(size.allFinite() && (size.array() >= kCsgShortestLength).all(), name,
                std::string(list) + " " + std::to_string(i) +
                    " needs hi above lo by at least 10 µm on every axis");
  }
}

void validate_cylinders(const std::vector<CsgCylinder>& cylinders, const std::string& name,
                        const char* list) {
  for (std::size_t i = 0; i < cylinders.size(); ++i) {
    const auto& c = cylinders[i];
    require_csg(c.base.allFinite() && c.axis.allFinite() && std::isfinite(c.radius) &&
                    c.axis.norm() >= kCsgShortestLength && c.radius >= kCsgShortestLength,
                name,
                std::string(list) + " " + std::to_string(i) +
                    " needs a length and a radius of at least 10 µm");
  }
}

gmsh::vectorpair add_primitives(const std::vector<CsgBox>& boxes,
                                const std::vector<CsgCylinder>& cylinders) {
  gmsh::vectorpair out;
  for (const auto& b : boxes) {
    const Eigen::Vector3d d = b.hi - b.lo;
    out.emplace_back(3, occ::addBox(b.lo.x(), b.lo.y(), b.lo.z(), d.x(), d.y(), d.z()));
  }
  for (const auto& c : cylinders)
    out.emplace_back(3, occ::addCylinder(c.base.x(), c.base.y(), c.base.z(), c.axis.x(), c.axis.y(),
                                         c.axis.z(), c.radius));
  return out;
}

int csg_one_volume(const gmsh::vectorpair& out, const std::string& name, const char* step) {
  std::vector<int> volumes;
  for (const auto& [dim, tag] : out)
    if (dim == 3) volumes.push_back(tag);
  if (volumes.size() != 1)
    throw std::runtime_error(
        name + ": " + step + " made " + std::to_string(volumes.size()) +
        " solids where one was expected (a part that falls apart, or nothing left)");
  return volumes.front();
}

// Gmsh's triangles of each face follow that face's own parametrisation, not the solid's outside:
// they are made to agree across every edge (which must join exactly two of them), then turned
// all at once if the enclosed volume comes out negative.
void orient_outward(io::SurfaceMesh& surface, const std::string& name) {
  using Edge = std::pair<std::uint32_t, std::uint32_t>;
  std::map<Edge, std::vector<std::size_t>> users;
  const auto key = [](std::uint32_t a, std::uint32_t b) {
    return Edge{std::min(a, b), std::max(a, b)};
  };
  for (std::size_t t = 0; t < surface.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      users[key(surface.triangles[t][k], surface.triangles[t][(k + 1) % 3])].push_back(t);
  for (const auto& [edge, ts] : users)
    if (ts.size() != 2)
      throw std::runtime_error(name + ": meshing left an edge joining " +
                               std::to_string(ts.size()) +
                               " triangles where a closed surface has two");
  const auto runs = [&](std::size_t t, std::uint32_t a, std::uint32_t b) {
    const auto& tri = surface.triangles[t];
    for (int k = 0; k < 3; ++k)
      if (tri[k] == a && tri[(k + 1) % 3] == b) return true;
    return false;
  };
  std::vector<bool> seen(surface.triangles.size(), false);
  std::vector<std::size_t> queue{0};
  seen[0] = true;
  std::size_t reached = 1;
  while (!queue.empty()) {
    const std::size_t t = queue.back();
    queue.pop_back();
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = surface.triangles[t][k], b = surface.triangles[t][(k + 1) % 3];
      for (std::size_t n : users[key(a, b)]) {
        if (n == t || seen[n]) continue;
        if (runs(n, a, b))
          std::swap(surface.triangles[n][1], surface.triangles[n][2]);  // must run b → a
        seen[n] = true;
        ++reached;
        queue.push_back(n);
      }
    }
  }
  if (reached != surface.triangles.size())
    throw std::runtime_error(
        name + ": the surface falls into more than one piece (a void inside the solid?)");
  if (enclosed_volume(surface) < 0)
    for (auto& tri : surface.triangles) std::swap(tri[1], tri[2]);
}

io::SurfaceMesh mesh_csg(const CsgSolid& solid, const std::string& name,
                         const CsgMeshing& meshing) {
  GmshSession session(name);
  gmsh::vectorpair added = add_primitives(solid.boxes, solid.cylinders);
  int volume = added.front().second;
  if (added.size() > 1) {
    gmsh::vectorpair out;
    std::vector<gmsh::vectorpair> map;
    occ::fuse({added.front()}, gmsh::vectorpair(added.begin() + 1, added.end()), out, map);
    volume = csg_one_volume(out, name, "joining the added shapes");
  }
  gmsh::vectorpair cuts = add_primitives(solid.box_cuts, solid.cylinder_cuts);
  if (!cuts.empty()) {
    gmsh::vectorpair out;
    std::vector<gmsh::vectorpair> map;
    occ::cut({{3, volume}}, cuts, out, map);
    volume = csg_one_volume(out, name, "cutting the holes");
  }
  occ::synchronize();
  // The boundary alone is meshed: a printer needs no inside, and filling it with tetrahedra as
  // fine as the smallest hole took a minute for five small parts.
  gmsh::option::setNumber("Mesh.MeshSizeMax", meshing.max_edge);
  gmsh::option::setNumber("Mesh.MeshSizeMin", 0.0);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", meshing.segments_per_circle);
  gmsh::option::setNumber("Mesh.ElementOrder", 1);
  gmsh::model::mesh::generate(2);
  session.throw_if_failed(name + ": meshing");

  gmsh::vectorpair faces;
  gmsh::model::getBoundary({{3, volume}}, faces, false, false, false);
  std::vector<std::size_t> node_tags;
  std::vector<double> coords, parametric;
  gmsh::model::mesh::getNodes(node_tags, coords, parametric, -1, -1, true, false);
  std::unordered_map<std::size_t, std::size_t> position;
  for (std::size_t i = 0; i < node_tags.size(); ++i) position[node_tags[i]] = i;

  io::SurfaceMesh surface;
  surface.name = name;
  std::unordered_map<std::size_t, std::uint32_t> dense;
  const auto vertex = [&](std::size_t tag) {
    auto [it, inserted] =
        dense.try_emplace(tag, static_cast<std::uint32_t>(surface.vertices.size()));
    if (inserted) {
      const std::size_t p = position.at(tag);
      surface.vertices.push_back({coords[3 * p], coords[3 * p + 1], coords[3 * p + 2]});
    }
    return it->second;
  };
  constexpr int kCsgTriangle3 = 2;  // Gmsh's element type: 3-node triangle
  for (const auto& [dim, tag] : faces) {
    std::vector<std::size_t> element_tags, nodes;
    gmsh::model::mesh::getElementsByType(kCsgTriangle3, element_tags, nodes, std::abs(tag));
    for (std::size_t e = 0; e + 3 <= nodes.size(); e += 3)
      surface.triangles.push_back({vertex(nodes[e]), vertex(nodes[e + 1]), vertex(nodes[e + 2])});
  }
  if (surface.triangles.empty()) throw std::runtime_error(name + ": meshing made no triangles");
  orient_outward(surface, name);
  return surface;
}

}  // namespace

void validate(const CsgSolid& solid, const std::string& name) {
  require_csg(!solid.boxes.empty() || !solid.cylinders.empty(), name,
              "a solid needs at least one box or cylinder");
  validate_boxes(solid.boxes, name, "box");
  validate_boxes(solid.box_cuts, name, "box cut");
  validate_cylinders(solid.cylinders, name, "cylinder");
  validate_cylinders(solid.cylinder_cuts, name, "cylinder cut");
}

io::SurfaceMesh csg_surface(const CsgSolid& solid, const std::string& name,
                            const CsgMeshing& meshing) {
  validate(solid, name);
  require_csg(std::isfinite(meshing.max_edge) && meshing.max_edge >= kCsgShortestLength, name,
              "the longest edge must be at least 10 µm");
  require_csg(meshing.segments_per_circle >= 8 && meshing.segments_per_circle <= 360, name,
              "facets per circle must lie between 8 and 360");
  return guard_gmsh(name + ": meshing", [&] { return mesh_csg(solid, name, meshing); });
}

}  // namespace nibrig::model::mechanics
