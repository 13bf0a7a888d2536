// Test and benchmark support: read the quadratic tetrahedra Gmsh has just generated into a TetMesh,
// with a node set "clamp" of the nodes on the plane x = 0. Header-only so that both the test
// suites and the benchmark program can use it without a library of their own. Gmsh keeps global
// state and is not thread-safe: use it from one thread, inside one GmshSession at a time.
#pragma once

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <unordered_map>
#include <vector>

#include "model/mechanics/tet_mesh.hpp"

namespace nibrig::test {

// gmsh::initialize/finalize around a scope, quiet, single-threaded, ignoring user config files.
class GmshSession {
 public:
  GmshSession() {
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.NumThreads", 1);
  }
  ~GmshSession() { gmsh::finalize(); }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
};

// Meshes the current OCC model (already synchronised) with second-order tetrahedra of at most
// `mesh_size` m; second-order nodes on curved surfaces are placed on the geometry (Gmsh's default).
inline void generate_quadratic_tets(double mesh_size) {
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeMax", mesh_size);
  gmsh::option::setNumber("Mesh.ElementOrder", 2);
  gmsh::model::mesh::generate(3);
}

// The current model's 10-node tetrahedra, one region "body". Nodes not used by a tetrahedron are
// dropped (Gmsh also returns nodes of lower-dimensional entities, all of them used here, but the
// compaction keeps the FEM's "node in no element" check from firing on meshes that have some).
inline model::mechanics::TetMesh tet_mesh_from_gmsh(double clamp_plane_x = 0.0) {
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> element_tags, element_nodes;
  gmsh::model::mesh::getElements(types, element_tags, element_nodes, 3);
  const std::vector<std::size_t>* tet_nodes = nullptr;
  for (std::size_t i = 0; i < types.size(); ++i) {
    if (types[i] != 11)  // 11: 10-node second-order tetrahedron
      throw std::runtime_error("gmsh mesh has 3D elements that are not 10-node tetrahedra");
    tet_nodes = &element_nodes[i];
  }
  if (tet_nodes == nullptr) throw std::runtime_error("gmsh mesh has no tetrahedra");

  std::vector<std::size_t> node_tags;
  std::vector<double> coords, parametric;
  gmsh::model::mesh::getNodes(node_tags, coords, parametric, -1, -1, false, false);
  std::unordered_map<std::size_t, std::size_t> position_of_tag;
  for (std::size_t i = 0; i < node_tags.size(); ++i) position_of_tag[node_tags[i]] = i;

  model::mechanics::TetMesh mesh;
  std::unordered_map<std::size_t, int> index_of_tag;
  std::vector<std::size_t> used;
  for (std::size_t i = 0; i < tet_nodes->size(); i += 10) {
    model::mechanics::Tet10 t;
    for (int a = 0; a < 10; ++a) {
      const std::size_t tag = (*tet_nodes)[i + static_cast<std::size_t>(a)];
      auto [it, inserted] = index_of_tag.try_emplace(tag, static_cast<int>(used.size()));
      if (inserted) used.push_back(position_of_tag.at(tag));
      t[static_cast<std::size_t>(a)] = it->second;
    }
    mesh.tets.push_back(t);
  }
  mesh.nodes.resize(3, static_cast<Eigen::Index>(used.size()));
  double extent = 0.0;
  for (std::size_t k = 0; k < used.size(); ++k) {
    for (int c = 0; c < 3; ++c) {
      mesh.nodes(c, static_cast<Eigen::Index>(k)) =
          coords[3 * used[k] + static_cast<std::size_t>(c)];
      extent = std::max(extent, std::abs(mesh.nodes(c, static_cast<Eigen::Index>(k))));
    }
  }
  mesh.tet_region.assign(mesh.tets.size(), 0);
  mesh.region_names = {"body"};
  // Gmsh puts nodes of a plane face exactly on it up to round-off of the CAD kernel.
  std::vector<int>& clamp = mesh.node_sets["clamp"];
  for (Eigen::Index k = 0; k < mesh.nodes.cols(); ++k)
    if (std::abs(mesh.nodes(0, k) - clamp_plane_x) <= 1e-12 * extent)
      clamp.push_back(static_cast<int>(k));
  return mesh;
}

}  // namespace nibrig::test
