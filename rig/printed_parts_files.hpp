// The rig's printed parts as the files a printer's operator takes (rig/PARTS.md): per part a 3MF
// (one object in millimetres, its material named, on a 200 × 200 mm bed), an STL, the PrusaSlicer
// settings its load asks for and a dimensioned drawing, and one recipe for all. The files go
// through the stylus's export path (model/io's STL and 3MF writers, each file written atomically).
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "model/io/surface_mesh.hpp"
#include "model/mechanics/csg_solid.hpp"
#include "rig/printed_parts.hpp"

namespace nibrig::rig {

struct MeshedPart {
  PrintedPart part;
  model::io::SurfaceMesh surface;  // metres, in print orientation
};

// The part's solid meshed (model/mechanics/csg_solid.hpp). Throws what csg_surface throws.
MeshedPart mesh_printed_part(const PrintedPart& part,
                             const model::mechanics::CsgMeshing& meshing = {});

// A PrusaSlicer config (the "key = value" lines of its .ini, the same as a 3MF's
// Metadata/Slic3r_PE.config) for the part: layers, perimeters, infill, material and temperatures,
// no supports, the 200 × 200 mm bed the 3MF is placed on. `--load` it beside the 3MF.
std::string prusa_slicer_ini(const PrintedPart& part);

struct RigPartFiles {
  std::filesystem::path three_mf, stl, ini, drawing;
};

struct RigPartsWritten {
  std::vector<RigPartFiles> parts;  // in rig_printed_parts' order
  std::filesystem::path recipe;     // rig_parts.json
  nlohmann::json recipe_json;       // what it holds, for a face to show
};

// Where write_rig_parts puts each part's files in `folder`: <name>.3mf, .stl, .ini, .svg.
RigPartFiles rig_part_files(const std::filesystem::path& folder, const PrintedPart& part);

// The recipe (kind "rig_parts"): the rig's derived heights, and per part its material, volume,
// bounding box on the bed, print settings, orientation and why, dimensions, hardware and files.
nlohmann::json rig_parts_recipe_json(const std::vector<MeshedPart>& parts,
                                     const std::vector<RigPartFiles>& files,
                                     const RigPartDimensions& d);

// Meshes every part, then writes its files and the recipe into `folder`: checked first (as the
// stylus's, model/design/stylus_export.hpp) and made when new; files of other names in it are left
// alone, and each file is written atomically. Throws std::runtime_error naming the file or part.
RigPartsWritten write_rig_parts(const std::filesystem::path& folder,
                                const RigPartDimensions& d = {},
                                const model::mechanics::CsgMeshing& meshing = {});

}  // namespace nibrig::rig
