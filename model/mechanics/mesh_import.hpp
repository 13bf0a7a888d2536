// Meshes a designer brings: the STL or STEP file they print, or a Gmsh .msh file they meshed
// themselves. Surfaces are checked before meshing (an STL must be a closed 2-manifold) and the
// result is the same TetMesh the parametric shapes give.
#pragma once

#include <filesystem>

#include "model/mechanics/tet_mesh.hpp"

namespace nibrig::model::mechanics {

struct MeshFileOptions {
  double unit_scale = 1.0;   // metres per file unit (0.001 for the usual millimetre STL/STEP)
  double mesh_size = 0.002;  // m, for STL and STEP; a .msh keeps its own elements
};

// .stl (ASCII or binary), .step/.stp, .brep, .msh, .3mf. Regions: a .msh file's named volume
// physical groups, a .3mf file's mesh objects by name (as `nibrig export` writes a stylus: their
// triangles kept, a face two objects share their interface; its own unit, unit_scale unused),
// else "body". Node sets: a .msh file's named lower-dimensional physical groups.
// Throws std::runtime_error naming the file and what is wrong: missing or unreadable, unknown
// extension, no surface, an open or non-manifold STL (with the offending edge), no tetrahedra.
TetMesh import_mesh_file(const std::filesystem::path& file, const MeshFileOptions& options);

}  // namespace nibrig::model::mechanics
