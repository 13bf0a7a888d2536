// Binary STL, the one format every slicer and mesh checker reads (admesh, PrusaSlicer): a surface
// in millimetres, the printing world's unit for STL, which carries none of its own.
#pragma once

#include <filesystem>

#include "model/io/surface_mesh.hpp"

namespace nibrig::model::mesh_io {

// The STL's bytes: an 80-byte header naming the surface (never starting "solid", which readers
// take for ASCII STL), the triangle count, and each triangle's unit normal and corners in mm.
// Throws std::invalid_argument naming the surface for a triangle index out of range.
std::string binary_stl(const io::SurfaceMesh& surface);

// binary_stl written atomically (atomic_file.hpp); throws naming the file.
void write_binary_stl(const std::filesystem::path& file, const io::SurfaceMesh& surface);

}  // namespace nibrig::model::mesh_io
