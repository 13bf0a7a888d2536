// Reading the PNGs the report figures write, independently of PLplot and cairo: the header fields
// from the bytes themselves, the pixels through stb_image.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "ui/report/colour_maps.hpp"

namespace nibrig::test {

std::vector<std::uint8_t> read_bytes(const std::filesystem::path& file);

// Width and height from the IHDR chunk; throws unless the file starts with the PNG signature
// followed by an IHDR chunk.
struct PngHeader {
  std::uint32_t width, height;
};
PngHeader png_header(const std::filesystem::path& file);

// 8-bit RGB pixels, row by row from the top.
struct RgbImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;
  ui::report::Rgb at(int x, int y) const;
};
RgbImage decode_png(const std::filesystem::path& file);

// Each channel within tolerance.
bool near(ui::report::Rgb a, ui::report::Rgb b, int tolerance);

}  // namespace nibrig::test
