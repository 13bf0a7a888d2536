// The mesh every mechanics computation works on: quadratic (10-node) tetrahedra with a material
// region per element and named node sets for boundary conditions. Geometry builders and file
// importers produce it; the FEM assembly and point evaluation consume it. Coordinates in metres.
#pragma once

#include <Eigen/Core>
#include <array>
#include <map>
#include <string>
#include <vector>

namespace nibrig::model::mechanics {

// Node order inside a tetrahedron is Gmsh's "Tetrahedron10": corners 0-3, then the nodes on edges
// (0,1) (1,2) (0,2) (0,3) (2,3) (1,3). On curved boundaries the edge nodes lie on the surface, not
// at the chord midpoint, so elements are isoparametric.
using Tet10 = std::array<int, 10>;

struct TetMesh {
  Eigen::Matrix3Xd nodes;                             // one column per node, metres
  std::vector<Tet10> tets;                            // indices into nodes' columns
  std::vector<int> tet_region;                        // per tet, index into region_names
  std::vector<std::string> region_names;              // material regions, e.g. "body", "tip"
  std::map<std::string, std::vector<int>> node_sets;  // e.g. "clamp": nodes held fixed (sorted)
};

}  // namespace nibrig::model::mechanics
