#include "model/mechanics/gmsh_session.hpp"

#include <gmsh.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <stdexcept>
#include <unordered_map>

#include "model/mechanics/mesh_repair.hpp"

namespace nibrig::model::mechanics {
namespace {

std::mutex& gmsh_mutex() {
  static std::mutex mutex;
  return mutex;
}

// A second session on the same thread would deadlock on the mutex; say so instead.
thread_local bool session_open_on_this_thread = false;

constexpr int kTet10 = 11;  // Gmsh element type: 10-node second-order tetrahedron
constexpr int kTet4 = 4;

bool is_error_line(const std::string& line) { return line.rfind("Error", 0) == 0; }

}  // namespace

GmshSession::GmshSession(const std::string& model_name) {
  if (session_open_on_this_thread)
    throw std::logic_error("GmshSession: nested sessions on one thread");
  lock_ = std::unique_lock<std::mutex>(gmsh_mutex());
  session_open_on_this_thread = true;
  gmsh::initialize(0, nullptr, false);  // no config files: results must not depend on the user's
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::option::setNumber("General.Verbosity", 2);  // errors and warnings reach the logger
  gmsh::option::setNumber("General.NumThreads", 1);
  gmsh::logger::start();
  gmsh::model::add(model_name);
}

GmshSession::~GmshSession() {
  gmsh::logger::stop();
  gmsh::finalize();
  session_open_on_this_thread = false;
}

std::vector<std::string> GmshSession::errors() const {
  std::vector<std::string> log;
  gmsh::logger::get(log);
  std::vector<std::string> errors;
  std::copy_if(log.begin(), log.end(), std::back_inserter(errors), is_error_line);
  return errors;
}

void GmshSession::throw_if_failed(const std::string& what) const {
  const auto found = errors();
  if (!found.empty()) throw std::runtime_error(what + ": " + found.front());
}

void generate_quadratic_tets(double max_size, double min_size) {
  gmsh::option::setNumber("Mesh.MeshSizeMax", max_size);
  gmsh::option::setNumber("Mesh.MeshSizeMin", min_size);
  // OpenCASCADE gives every point a default size from the model's extent, which would cap the
  // element size of a small part below what the caller asked for.
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  // Resolve curved features (a 1 mm tip on a 10 mm body) without refining the whole body. Eight
  // elements per circle: a quadratic edge follows a 45° arc to 0.07 % of its radius. Twelve
  // made the bundled stylus 60 % larger and its 64 modes 2.6 times slower for no change that
  // matters (first mode 0.02 %, 64th 0.2 %).
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 8);
  gmsh::option::setNumber("Mesh.ElementOrder", 2);
  gmsh::option::setNumber("Mesh.SecondOrderLinear", 0);
  gmsh::option::setNumber("Mesh.Optimize", 1);
  guard_gmsh("meshing", [] { gmsh::model::mesh::generate(3); });
  // Moving edge nodes onto a curved surface can fold a small element near a tip (seen on the 2 mm
  // tip stylus at 3 mm elements); Debian's Gmsh 4.8 has no working high-order optimiser to untangle
  // it, so tet_mesh_from_gmsh straightens such elements instead (mesh_repair.hpp).
}

TetMesh tet_mesh_from_gmsh(const std::string& default_region) {
  gmsh::vectorpair volumes;
  gmsh::model::getEntities(volumes, 3);
  bool first_order = false;
  for (const auto& [dim, tag] : volumes) {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> element_tags, node_tags;
    gmsh::model::mesh::getElements(types, element_tags, node_tags, dim, tag);
    first_order |= std::find(types.begin(), types.end(), kTet4) != types.end();
  }
  if (first_order) gmsh::model::mesh::setOrder(2);

  std::vector<std::size_t> all_tags;
  std::vector<double> all_coords, parametric;
  gmsh::model::mesh::getNodes(all_tags, all_coords, parametric, -1, -1, true, false);
  std::unordered_map<std::size_t, std::size_t> gmsh_position;
  for (std::size_t i = 0; i < all_tags.size(); ++i) gmsh_position[all_tags[i]] = i;

  TetMesh mesh;
  std::unordered_map<std::size_t, int> dense_index;  // only nodes that a tetrahedron uses
  std::vector<double> used_coords;
  auto dense = [&](std::size_t gmsh_tag) {
    auto [it, inserted] = dense_index.try_emplace(gmsh_tag, static_cast<int>(dense_index.size()));
    if (inserted) {
      const std::size_t p = gmsh_position.at(gmsh_tag);
      used_coords.insert(used_coords.end(), &all_coords[3 * p], &all_coords[3 * p] + 3);
    }
    return it->second;
  };
  for (const auto& [dim, tag] : volumes) {
    std::string region = default_region;
    std::vector<int> groups;
    gmsh::model::getPhysicalGroupsForEntity(dim, tag, groups);
    if (!groups.empty()) {
      std::string name;
      gmsh::model::getPhysicalName(dim, groups.front(), name);
      if (!name.empty()) region = name;
    }
    auto found = std::find(mesh.region_names.begin(), mesh.region_names.end(), region);
    const int region_index = static_cast<int>(found - mesh.region_names.begin());
    if (found == mesh.region_names.end()) mesh.region_names.push_back(region);

    std::vector<int> types;
    std::vector<std::vector<std::size_t>> element_tags, node_tags;
    gmsh::model::mesh::getElements(types, element_tags, node_tags, dim, tag);
    for (std::size_t t = 0; t < types.size(); ++t) {
      if (types[t] != kTet10) continue;
      const auto& nodes = node_tags[t];
      for (std::size_t e = 0; e + 10 <= nodes.size(); e += 10) {
        Tet10 tet;
        for (int k = 0; k < 10; ++k) tet[k] = dense(nodes[e + k]);
        mesh.tets.push_back(tet);
        mesh.tet_region.push_back(region_index);
      }
    }
  }
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups);
  for (const auto& [dim, tag] : groups) {
    std::string name;
    gmsh::model::getPhysicalName(dim, tag, name);
    if (dim == 3 || name.empty()) continue;
    std::vector<std::size_t> group_nodes;
    std::vector<double> group_coords;
    gmsh::model::mesh::getNodesForPhysicalGroup(dim, tag, group_nodes, group_coords);
    auto& set = mesh.node_sets[name];
    for (std::size_t gmsh_tag : group_nodes) {
      auto it = dense_index.find(gmsh_tag);
      if (it != dense_index.end()) set.push_back(it->second);
    }
    std::sort(set.begin(), set.end());
    set.erase(std::unique(set.begin(), set.end()), set.end());
  }
  mesh.nodes = Eigen::Map<const Eigen::Matrix3Xd>(
      used_coords.data(), 3, static_cast<Eigen::Index>(used_coords.size() / 3));
  const std::size_t straightened = straighten_inverted_elements(mesh);
  if (straightened > 0)
    spdlog::debug("straightened {} curved element(s) that Gmsh had folded", straightened);
  return mesh;
}

}  // namespace nibrig::model::mechanics
