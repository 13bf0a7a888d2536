#include "model/mechanics/mesh_import.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

#include "model/mechanics/gmsh_session.hpp"
#include "model/mechanics/shape_builders.hpp"
#include "model/mesh_io/stylus_3mf.hpp"

namespace nibrig::model::mechanics {
namespace {

constexpr int kTriangle3 = 2;  // Gmsh element type of a linear triangle

std::runtime_error file_error(const std::filesystem::path& file, const std::string& problem) {
  return std::runtime_error(file.string() + ": " + problem);
}

std::string lower_extension(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext;
}

std::string point_text(const std::unordered_map<std::size_t, std::size_t>& position,
                       const std::vector<double>& coords, std::size_t tag) {
  const std::size_t p = position.at(tag);
  std::ostringstream out;
  out << "(" << coords[3 * p] << ", " << coords[3 * p + 1] << ", " << coords[3 * p + 2] << ")";
  return out.str();
}

// A closed 2-manifold surface has every edge in exactly two triangles: one means a hole, three or
// more a fin or two bodies touching along an edge. Either would give Gmsh no well-defined inside.
void check_closed_manifold(const std::filesystem::path& file) {
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> element_tags, node_tags;
  gmsh::model::mesh::getElements(types, element_tags, node_tags, 2);
  std::map<std::pair<std::size_t, std::size_t>, int> edge_use;
  std::size_t triangles = 0;
  for (std::size_t t = 0; t < types.size(); ++t) {
    if (types[t] != kTriangle3) continue;
    const auto& n = node_tags[t];
    triangles += n.size() / 3;
    for (std::size_t e = 0; e + 3 <= n.size(); e += 3)
      for (int k = 0; k < 3; ++k) {
        const std::size_t a = n[e + k], b = n[e + (k + 1) % 3];
        ++edge_use[{std::min(a, b), std::max(a, b)}];
      }
  }
  if (triangles == 0) throw file_error(file, "contains no triangles");
  for (const auto& [edge, uses] : edge_use) {
    if (uses == 2) continue;
    std::vector<std::size_t> tags;
    std::vector<double> coords, parametric;
    gmsh::model::mesh::getNodes(tags, coords, parametric, -1, -1, true, false);
    std::unordered_map<std::size_t, std::size_t> position;
    for (std::size_t i = 0; i < tags.size(); ++i) position[tags[i]] = i;
    const std::string where = "the edge from " + point_text(position, coords, edge.first) + " to " +
                              point_text(position, coords, edge.second) +
                              " (file units) belongs to " + std::to_string(uses) +
                              (uses == 1 ? " triangle" : " triangles");
    throw file_error(file, uses == 1 ? "the surface is not closed: " + where
                                     : "the surface is not a 2-manifold: " + where +
                                           " (a closed surface has exactly two at every edge)");
  }
}

void volume_from_stl_surface() {
  // Split the triangulation into smooth patches (sharp edges above 40°) that Gmsh can remesh, then
  // fill the closed shell with a volume.
  gmsh::model::mesh::classifySurfaces(40 * M_PI / 180, true, true, M_PI);
  gmsh::model::mesh::createGeometry();
  gmsh::vectorpair surfaces;
  gmsh::model::getEntities(surfaces, 2);
  std::vector<int> surface_tags;
  for (const auto& [dim, tag] : surfaces) surface_tags.push_back(tag);
  const int loop = gmsh::model::geo::addSurfaceLoop(surface_tags);
  gmsh::model::geo::addVolume({loop});
  gmsh::model::geo::synchronize();
}

TetMesh import_checked_file(const std::filesystem::path& file, const MeshFileOptions& options,
                            bool stl, bool step, bool msh);

// The regions' closed surfaces as Gmsh discrete surfaces, their triangulation kept: a triangle in
// two regions is their interface, one surface shared by both volumes, so the tetrahedra meet
// node to node across it. Coordinates are in the file's unit; a volume per region, its physical
// group named after it.
void volumes_from_region_surfaces(const std::filesystem::path& file,
                                  const std::vector<mesh_io::ThreeMfRegion>& regions) {
  std::map<std::array<double, 3>, std::size_t> node_of;
  std::vector<std::size_t> node_tags;
  std::vector<double> coords;
  // Sorted corner tags -> (region, the triangle's nodes as wound by the first region that has it).
  struct Use {
    std::vector<int> regions;
    std::array<std::size_t, 3> nodes;
  };
  std::map<std::array<std::size_t, 3>, Use> triangles;
  for (std::size_t r = 0; r < regions.size(); ++r) {
    const auto& s = regions[r].surface;
    if (s.triangles.empty()) throw file_error(file, "region '" + s.name + "' has no triangles");
    std::vector<std::size_t> tag(s.vertices.size());
    for (std::size_t v = 0; v < s.vertices.size(); ++v) {
      auto [it, inserted] = node_of.emplace(s.vertices[v], node_of.size() + 1);
      if (inserted) {
        node_tags.push_back(it->second);
        coords.insert(coords.end(), s.vertices[v].begin(), s.vertices[v].end());
      }
      tag[v] = it->second;
    }
    for (const auto& t : s.triangles) {
      std::array<std::size_t, 3> nodes{tag.at(t[0]), tag.at(t[1]), tag.at(t[2])};
      auto key = nodes;
      std::sort(key.begin(), key.end());
      auto [it, inserted] = triangles.emplace(key, Use{{}, nodes});
      it->second.regions.push_back(static_cast<int>(r));
    }
  }
  // One discrete surface per region's outside and per pair's interface.
  std::map<std::pair<int, int>, std::vector<std::size_t>> surfaces;
  for (const auto& [key, use] : triangles) {
    if (use.regions.size() > 2)
      throw file_error(file, "a triangle is shared by " + std::to_string(use.regions.size()) +
                                 " regions (two at most touch along a face)");
    const std::pair<int, int> group =
        use.regions.size() == 1 ? std::pair{use.regions[0], -1}
                                : std::pair{std::min(use.regions[0], use.regions[1]), std::max(use.regions[0], use.regions[1])};
    auto& flat = surfaces[group];
    flat.insert(flat.end(), use.nodes.begin(), use.nodes.end());
  }
  std::map<int, std::vector<int>> bounds;  // region -> its surfaces
  int surface_tag = 0;
  for (const auto& [group, flat] : surfaces) {
    gmsh::model::addDiscreteEntity(2, ++surface_tag);
    if (surface_tag == 1) gmsh::model::mesh::addNodes(2, 1, node_tags, coords);
    gmsh::model::mesh::addElementsByType(surface_tag, kTriangle3, {}, flat);
    bounds[group.first].push_back(surface_tag);
    if (group.second >= 0) bounds[group.second].push_back(surface_tag);
  }
  std::vector<int> volumes;
  for (std::size_t r = 0; r < regions.size(); ++r) {
    const int loop = gmsh::model::geo::addSurfaceLoop(bounds[static_cast<int>(r)]);
    volumes.push_back(gmsh::model::geo::addVolume({loop}));
  }
  gmsh::model::geo::synchronize();
  for (std::size_t r = 0; r < regions.size(); ++r) {
    gmsh::model::addPhysicalGroup(3, {volumes[r]}, volumes[r]);
    gmsh::model::setPhysicalName(3, volumes[r], regions[r].surface.name);
  }
}

}  // namespace

TetMesh import_mesh_file(const std::filesystem::path& file, const MeshFileOptions& options) {
  if (!(std::isfinite(options.unit_scale) && options.unit_scale > 0))
    throw std::invalid_argument("unit scale must be positive (metres per file unit)");
  validate_mesh_size(options.mesh_size);
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error)) throw file_error(file, "no such file");
  const std::string ext = lower_extension(file);
  const bool stl = ext == ".stl", step = ext == ".step" || ext == ".stp" || ext == ".brep",
             msh = ext == ".msh";
  if (ext == ".3mf") {
    // A 3MF carries its own unit; its regions come back in metres.
    const auto regions = mesh_io::read_3mf_regions(file);
    if (regions.empty()) throw file_error(file, "contains no mesh object");
    return guard_gmsh(file.string(), [&] {
      GmshSession session("imported");
      volumes_from_region_surfaces(file, regions);
      generate_quadratic_tets(options.mesh_size, options.mesh_size / 10);
      session.throw_if_failed(file.string() + ": meshing");
      TetMesh mesh = tet_mesh_from_gmsh("body");
      if (mesh.tets.empty()) throw file_error(file, "meshing made no tetrahedra");
      return mesh;
    });
  }
  if (!stl && !step && !msh)
    throw file_error(
        file, "unknown mesh format '" + ext + "' (expected .stl, .step, .stp, .brep, .msh or .3mf)");

  return guard_gmsh(file.string(),
                    [&] { return import_checked_file(file, options, stl, step, msh); });
}

namespace {

TetMesh import_checked_file(const std::filesystem::path& file, const MeshFileOptions& options,
                            bool stl, bool step, bool msh) {
  GmshSession session("imported");
  const double size_in_file_units = options.mesh_size / options.unit_scale;
  if (step) {
    gmsh::vectorpair shapes;
    gmsh::model::occ::importShapes(file.string(), shapes);
    session.throw_if_failed(file.string() + ": reading");
    gmsh::model::occ::synchronize();
    gmsh::vectorpair volumes;
    gmsh::model::getEntities(volumes, 3);
    if (volumes.empty())
      throw file_error(file, "contains no solid (a STEP file of surfaces only cannot be meshed)");
  } else {
    gmsh::merge(file.string());
    session.throw_if_failed(file.string() + ": reading");
    if (stl) {
      check_closed_manifold(file);
      volume_from_stl_surface();
    }
  }
  if (!msh) generate_quadratic_tets(size_in_file_units, size_in_file_units / 10);
  session.throw_if_failed(file.string() + ": meshing");
  TetMesh mesh = tet_mesh_from_gmsh("body");
  if (mesh.tets.empty())
    throw file_error(file, msh ? "contains no tetrahedra" : "meshing made no tetrahedra");
  mesh.nodes *= options.unit_scale;
  return mesh;
}

}  // namespace

}  // namespace nibrig::model::mechanics
