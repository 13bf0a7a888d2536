// A multi-material part as a 3MF file, written with lib3mf (the 3MF consortium's library): one
// mesh object per material region, each with its base material, assembled into one components
// object so that a slicer loads one part of several volumes, placed by one build item. Units are
// millimetres, as printers expect.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "model/io/surface_mesh.hpp"

namespace nibrig::model::mesh_io {

struct ThreeMfRegion {
  io::SurfaceMesh surface;  // metres; its name names the object
  std::string material;     // the base material's name: what to load into the printer for it
  std::array<std::uint8_t, 3> display_rgb{200, 200, 200};
};

struct ThreeMfPart {
  std::string name;
  std::vector<ThreeMfRegion> regions;
  // 3MF's well-known metadata (Title, Description, Application, …), in order.
  std::vector<std::pair<std::string, std::string>> metadata;
  std::array<double, 3> placement_m{0, 0, 0};  // the build item's translation
  // Files the package carries beside the model, by their path in it: a slicer's own settings
  // ("Metadata/Slic3r_PE.config", which PrusaSlicer reads on opening the 3MF).
  std::vector<std::pair<std::string, std::string>> attachments;
};

// Written atomically (atomic_file.hpp). Throws std::runtime_error naming the file and lib3mf's
// error; std::invalid_argument for a part without regions or a region without triangles.
void write_3mf(const std::filesystem::path& file, const ThreeMfPart& part);

// What a 3MF file holds, read back with lib3mf: each mesh object's surface (metres) and name, and
// its base material's name. For the tests and for re-importing an exported part.
std::vector<ThreeMfRegion> read_3mf_regions(const std::filesystem::path& file);

}  // namespace nibrig::model::mesh_io
