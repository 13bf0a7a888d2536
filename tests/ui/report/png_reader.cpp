#include "tests/ui/report/png_reader.hpp"

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <stdexcept>

// The one place the decoder is compiled: static, so it can never clash with a libstb linked later.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb/stb_image.h>

namespace nibrig::test {

std::vector<std::uint8_t> read_bytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open " + file.string());
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

PngHeader png_header(const std::filesystem::path& file) {
  const auto bytes = read_bytes(file);
  static const std::uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  if (bytes.size() < 24 || !std::equal(signature, signature + 8, bytes.begin())) {
    throw std::runtime_error(file.string() + ": no PNG signature");
  }
  if (std::string(bytes.begin() + 12, bytes.begin() + 16) != "IHDR") {
    throw std::runtime_error(file.string() + ": first chunk is not IHDR");
  }
  const auto be32 = [&](std::size_t at) {
    return (std::uint32_t{bytes[at]} << 24) | (std::uint32_t{bytes[at + 1]} << 16) |
           (std::uint32_t{bytes[at + 2]} << 8) | std::uint32_t{bytes[at + 3]};
  };
  return {be32(16), be32(20)};
}

ui::report::Rgb RgbImage::at(int x, int y) const {
  const auto i = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                      static_cast<std::size_t>(x));
  return {pixels[i], pixels[i + 1], pixels[i + 2]};
}

RgbImage decode_png(const std::filesystem::path& file) {
  int w = 0, h = 0, channels = 0;
  stbi_uc* data = stbi_load(file.c_str(), &w, &h, &channels, 3);
  if (data == nullptr) {
    throw std::runtime_error(file.string() +
                             ": stb_image cannot decode it: " + stbi_failure_reason());
  }
  RgbImage image;
  image.width = w;
  image.height = h;
  image.pixels.assign(data, data + static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3);
  stbi_image_free(data);
  return image;
}

bool near(ui::report::Rgb a, ui::report::Rgb b, int tolerance) {
  return std::abs(a.r - b.r) <= tolerance && std::abs(a.g - b.g) <= tolerance &&
         std::abs(a.b - b.b) <= tolerance;
}

}  // namespace nibrig::test
