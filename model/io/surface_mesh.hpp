// A closed triangulated surface, as printers and slicers take a solid: vertices in metres and
// triangles wound counter-clockwise seen from outside. What the mechanics hands the file writers
// (STL, 3MF), which know nothing of meshes or designs.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace nibrig::model::io {

struct SurfaceMesh {
  std::string name;                                      // e.g. the material region, "body"
  std::vector<std::array<double, 3>> vertices;           // metres
  std::vector<std::array<std::uint32_t, 3>> triangles;   // indices into vertices
};

}  // namespace nibrig::model::io
