// The boundary of each material region of a mesh, as the FEM meshed it: what a printer gets, so
// that the printed solid is the one whose modes were computed. Each quadratic tetrahedron's face
// on a region's boundary is a curved patch (its six nodes, on the true surface where the shape is
// curved); it is cut into flat triangles at points of that patch, so the facets follow the
// element's own geometry.
#pragma once

#include <vector>

#include "model/io/surface_mesh.hpp"
#include "model/mechanics/tet_mesh.hpp"

namespace nibrig::model::mechanics {

// Each face cut into subdivisions² triangles. 2 puts a vertex at each of the element's six nodes
// and nowhere else: the printed surface is the FEM's own nodes joined flat. More follow the
// element's curved patch closer (a facet's sagitta falls as 1/subdivisions²) at the cost of a
// file, and a re-meshing of it, growing as subdivisions².
inline constexpr int kSurfaceSubdivisions = 2;

// One closed surface per region, in mesh.region_names' order and named after it, wound outward.
// Two regions that touch share their interface's vertices exactly (opposite windings). Throws
// std::invalid_argument for a mesh without tetrahedra, a region with none, or subdivisions < 1.
std::vector<io::SurfaceMesh> region_surfaces(const TetMesh& mesh, int subdivisions = kSurfaceSubdivisions);

// The volume a closed outward-wound surface encloses (divergence theorem), m³.
double enclosed_volume(const io::SurfaceMesh& surface);

}  // namespace nibrig::model::mechanics
