// The boundary of each material region of a mesh, as the FEM meshed it: what a printer gets, so
// that the printed solid is the one whose modes were computed. Each quadratic tetrahedron's face
// on a region's boundary (its six nodes on the curved surface where the shape is curved) becomes
// four flat triangles through its corner and edge nodes.
#pragma once

#include <vector>

#include "model/io/surface_mesh.hpp"
#include "model/mechanics/tet_mesh.hpp"

namespace nibrig::model::mechanics {

// One closed surface per region, in mesh.region_names' order and named after it, wound outward.
// Two regions that touch share their interface's vertices exactly (opposite windings). Throws
// std::invalid_argument for a mesh without tetrahedra or a region with none.
std::vector<io::SurfaceMesh> region_surfaces(const TetMesh& mesh);

// The volume a closed outward-wound surface encloses (divergence theorem), m³.
double enclosed_volume(const io::SurfaceMesh& surface);

}  // namespace nibrig::model::mechanics
