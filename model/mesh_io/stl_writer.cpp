#include "model/mesh_io/stl_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "model/io/atomic_file.hpp"

namespace nibrig::model::mesh_io {
namespace {

void put_u32(std::string& out, std::uint32_t v) {
  char bytes[4];
  for (int i = 0; i < 4; ++i) bytes[i] = static_cast<char>((v >> (8 * i)) & 0xff);
  out.append(bytes, 4);
}

void put_f32(std::string& out, double v) {
  const float f = static_cast<float>(v);
  std::uint32_t bits = 0;
  std::memcpy(&bits, &f, 4);
  put_u32(out, bits);
}

}  // namespace

std::string binary_stl(const io::SurfaceMesh& surface) {
  std::string out;
  out.reserve(84 + 50 * surface.triangles.size());
  std::string header = "nibrig stylus region " + surface.name + " (mm)";
  header.resize(80, ' ');
  out += header;
  put_u32(out, static_cast<std::uint32_t>(surface.triangles.size()));
  const std::size_t n = surface.vertices.size();
  for (const auto& t : surface.triangles) {
    if (t[0] >= n || t[1] >= n || t[2] >= n)
      throw std::invalid_argument("surface '" + surface.name + "': a triangle names vertex " +
                                  std::to_string(std::max({t[0], t[1], t[2]})) + " of " +
                                  std::to_string(n));
    const auto& a = surface.vertices[t[0]];
    const auto& b = surface.vertices[t[1]];
    const auto& c = surface.vertices[t[2]];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    double normal[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                        u[0] * v[1] - u[1] * v[0]};
    const double length =
        std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
    for (double& x : normal) x = length > 0 ? x / length : 0.0;
    for (double x : normal) put_f32(out, x);
    for (const auto* p : {&a, &b, &c})
      for (double x : *p) put_f32(out, 1e3 * x);
    out += std::string(2, '\0');  // attribute byte count
  }
  return out;
}

void write_binary_stl(const std::filesystem::path& file, const io::SurfaceMesh& surface) {
  io::write_file_atomically(file, binary_stl(surface));
}

}  // namespace nibrig::model::mesh_io
