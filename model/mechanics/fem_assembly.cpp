#include "model/mechanics/fem_assembly.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "model/mechanics/tet10_element.hpp"

namespace nibrig::model::mechanics {
namespace {

[[noreturn]] void fail(const std::string& message) { throw std::invalid_argument(message); }

void validate_mesh(const TetMesh& mesh, const std::vector<IsotropicMaterial>& materials) {
  const auto node_count = static_cast<long>(mesh.nodes.cols());
  if (!mesh.nodes.allFinite()) fail("the mesh has a node with a non-finite coordinate");
  if (mesh.tets.empty()) fail("the mesh has no elements");
  if (mesh.tet_region.size() != mesh.tets.size()) {
    std::ostringstream s;
    s << "the mesh has " << mesh.tets.size() << " elements but " << mesh.tet_region.size()
      << " region indices";
    fail(s.str());
  }
  if (materials.size() != mesh.region_names.size()) {
    std::ostringstream s;
    if (materials.size() < mesh.region_names.size()) {
      s << "region '" << mesh.region_names[materials.size()]
        << "' has no material: " << materials.size() << " materials for "
        << mesh.region_names.size() << " regions";
    } else {
      s << materials.size() << " materials for " << mesh.region_names.size() << " regions";
    }
    fail(s.str());
  }
  for (const auto& m : materials) validate(m);
  for (std::size_t e = 0; e < mesh.tets.size(); ++e) {
    for (int n : mesh.tets[e]) {
      if (n < 0 || n >= node_count) {
        std::ostringstream s;
        s << "element " << e << " refers to node " << n << ", but the mesh has " << node_count
          << " nodes";
        fail(s.str());
      }
    }
    const int r = mesh.tet_region[e];
    if (r < 0 || static_cast<std::size_t>(r) >= mesh.region_names.size()) {
      std::ostringstream s;
      s << "element " << e << " is in region " << r << ", but the mesh has "
        << mesh.region_names.size() << " regions";
      fail(s.str());
    }
  }
}

std::vector<char> held_nodes(const TetMesh& mesh, const std::vector<std::string>& sets) {
  std::vector<char> held(static_cast<std::size_t>(mesh.nodes.cols()), 0);
  for (const auto& name : sets) {
    const auto it = mesh.node_sets.find(name);
    if (it == mesh.node_sets.end()) fail("the mesh has no node set '" + name + "' to hold fixed");
    if (it->second.empty())
      fail("the mesh has no clamped region: node set '" + name + "' is empty");
    for (int n : it->second) {
      if (n < 0 || n >= mesh.nodes.cols()) {
        std::ostringstream s;
        s << "node set '" << name << "' refers to node " << n << ", but the mesh has "
          << mesh.nodes.cols() << " nodes";
        fail(s.str());
      }
      held[static_cast<std::size_t>(n)] = 1;
    }
  }
  return held;
}

// Compressed lists: items of group g are items[offsets[g] .. offsets[g+1]).
struct Csr {
  std::vector<int> offsets;
  std::vector<int> items;
  int size(int g) const { return offsets[g + 1] - offsets[g]; }
  const int* begin(int g) const { return items.data() + offsets[g]; }
  const int* end(int g) const { return items.data() + offsets[g + 1]; }
};

Csr elements_of_nodes(const TetMesh& mesh) {
  const auto n = static_cast<std::size_t>(mesh.nodes.cols());
  Csr c;
  c.offsets.assign(n + 1, 0);
  for (const auto& t : mesh.tets)
    for (int v : t) ++c.offsets[v + 1];
  for (std::size_t i = 0; i < n; ++i) {
    if (c.offsets[i + 1] == 0) {
      std::ostringstream s;
      s << "node " << i << " belongs to no element (it would have no mass)";
      fail(s.str());
    }
    c.offsets[i + 1] += c.offsets[i];
  }
  c.items.resize(static_cast<std::size_t>(c.offsets[n]));
  std::vector<int> fill(c.offsets.begin(), c.offsets.end() - 1);
  for (std::size_t e = 0; e < mesh.tets.size(); ++e)
    for (int v : mesh.tets[e]) c.items[fill[v]++] = static_cast<int>(e);
  return c;
}

// For each free node (in free numbering), the sorted free nodes it shares an element with
// (itself included): the block sparsity pattern of K and M.
Csr free_adjacency(const TetMesh& mesh, const Csr& elements, const std::vector<int>& free_of_node,
                   const std::vector<int>& node_of_free) {
  Csr adj;
  adj.offsets.assign(node_of_free.size() + 1, 0);
  std::vector<int> scratch;
  for (std::size_t k = 0; k < node_of_free.size(); ++k) {
    const int node = node_of_free[k];
    scratch.clear();
    for (const int* e = elements.begin(node); e != elements.end(node); ++e)
      for (int v : mesh.tets[*e])
        if (free_of_node[v] >= 0) scratch.push_back(free_of_node[v]);
    std::sort(scratch.begin(), scratch.end());
    scratch.erase(std::unique(scratch.begin(), scratch.end()), scratch.end());
    adj.items.insert(adj.items.end(), scratch.begin(), scratch.end());
    adj.offsets[k + 1] = static_cast<int>(adj.items.size());
  }
  return adj;
}

// K's column 3k+j holds rows 3m+i for every m adjacent to k and every i; M's column 3k+j only the
// rows 3m+j, since the consistent mass does not couple components.
void build_patterns(const Csr& adj, Eigen::SparseMatrix<double>& k,
                    Eigen::SparseMatrix<double>& m) {
  const int nodes = static_cast<int>(adj.offsets.size()) - 1;
  const Eigen::Index dofs = 3 * static_cast<Eigen::Index>(nodes);
  k.resize(dofs, dofs);
  m.resize(dofs, dofs);
  k.resizeNonZeros(9 * static_cast<Eigen::Index>(adj.items.size()));
  m.resizeNonZeros(3 * static_cast<Eigen::Index>(adj.items.size()));
  int* k_outer = k.outerIndexPtr();
  int* m_outer = m.outerIndexPtr();
  int* k_inner = k.innerIndexPtr();
  int* m_inner = m.innerIndexPtr();
  for (int n = 0; n < nodes; ++n) {
    const int deg = adj.size(n);
    for (int j = 0; j < 3; ++j) {
      const int k_start = 9 * adj.offsets[n] + 3 * j * deg;
      const int m_start = 3 * adj.offsets[n] + j * deg;
      k_outer[3 * n + j] = k_start;
      m_outer[3 * n + j] = m_start;
      for (int p = 0; p < deg; ++p) {
        const int row_node = adj.begin(n)[p];
        for (int i = 0; i < 3; ++i) k_inner[k_start + 3 * p + i] = 3 * row_node + i;
        m_inner[m_start + p] = 3 * row_node + j;
      }
    }
  }
  k_outer[dofs] = 9 * static_cast<int>(adj.items.size());
  m_outer[dofs] = 3 * static_cast<int>(adj.items.size());
  std::fill_n(k.valuePtr(), k.nonZeros(), 0.0);
  std::fill_n(m.valuePtr(), m.nonZeros(), 0.0);
}

}  // namespace

Eigen::MatrixXd FemSystem::expand(const Eigen::MatrixXd& free_values) const {
  if (free_values.rows() != free_dofs()) {
    std::ostringstream s;
    s << "expand: " << free_values.rows() << " rows given, the system has " << free_dofs()
      << " free DOFs";
    throw std::invalid_argument(s.str());
  }
  Eigen::MatrixXd full = Eigen::MatrixXd::Zero(full_dofs(), free_values.cols());
  for (std::size_t f = 0; f < free_to_full.size(); ++f)
    full.row(free_to_full[f]) = free_values.row(static_cast<Eigen::Index>(f));
  return full;
}

FemSystem assemble(const TetMesh& mesh, const std::vector<IsotropicMaterial>& region_materials,
                   const std::vector<std::string>& held_node_sets) {
  validate_mesh(mesh, region_materials);
  const std::vector<char> held = held_nodes(mesh, held_node_sets);
  const Csr elements = elements_of_nodes(mesh);
  for (std::size_t e = 0; e < mesh.tets.size(); ++e) check_tet10(tet10_nodes(mesh, e), e);

  FemSystem sys;
  const auto node_count = static_cast<std::size_t>(mesh.nodes.cols());
  std::vector<int> free_of_node(node_count, -1), node_of_free;
  for (std::size_t n = 0; n < node_count; ++n) {
    if (held[n]) continue;
    free_of_node[n] = static_cast<int>(node_of_free.size());
    node_of_free.push_back(static_cast<int>(n));
  }
  if (node_of_free.empty()) fail("every node of the mesh is held fixed: nothing can move");
  sys.full_to_free.assign(3 * node_count, -1);
  for (std::size_t k = 0; k < node_of_free.size(); ++k) {
    for (int c = 0; c < 3; ++c) {
      sys.full_to_free[3 * node_of_free[k] + c] = static_cast<int>(3 * k + c);
      sys.free_to_full.push_back(3 * node_of_free[k] + c);
    }
  }

  const Csr adj = free_adjacency(mesh, elements, free_of_node, node_of_free);
  build_patterns(adj, sys.stiffness, sys.mass);

  std::vector<LameParameters> lame;
  for (const auto& m : region_materials) lame.push_back(lame_parameters(m));
  double* kv = sys.stiffness.valuePtr();
  double* mv = sys.mass.valuePtr();
  for (std::size_t e = 0; e < mesh.tets.size(); ++e) {
    const Tet10Nodes x = tet10_nodes(mesh, e);
    const int region = mesh.tet_region[e];
    const Tet10Matrix ke = tet10_stiffness(x, lame[region]);
    const Tet10ScalarMatrix me = tet10_scalar_mass(x, region_materials[region].density);
    std::array<int, 10> f;
    for (int a = 0; a < 10; ++a) f[a] = free_of_node[mesh.tets[e][a]];
    for (int b = 0; b < 10; ++b) {
      if (f[b] < 0) continue;
      const int deg = adj.size(f[b]);
      for (int a = 0; a < 10; ++a) {
        if (f[a] < 0) continue;
        const int p = static_cast<int>(std::lower_bound(adj.begin(f[b]), adj.end(f[b]), f[a]) -
                                       adj.begin(f[b]));
        const int k_base = 9 * adj.offsets[f[b]] + 3 * p;
        const int m_base = 3 * adj.offsets[f[b]] + p;
        for (int j = 0; j < 3; ++j) {
          for (int i = 0; i < 3; ++i) kv[k_base + 3 * j * deg + i] += ke(3 * a + i, 3 * b + j);
          mv[m_base + j * deg] += me(a, b);
        }
      }
    }
  }
  return sys;
}

}  // namespace nibrig::model::mechanics
