#include "tests/rt/test_voices.hpp"

#include "rt/voice_builder.hpp"

#include <stdexcept>

#include "model/io/catalog_file.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::rt::testing {

model::io::VelocitySpectrum catalog_spectrum(const std::string& tool, const std::string& surface) {
  static const auto catalog = model::io::read_catalog(nibrig::test::assets_dir() / "default_catalog.json");
  for (const auto& p : catalog.pairings)
    if (p.tool == tool && p.surface == surface && p.vibration) return p.vibration->spectrum;
  throw std::runtime_error("the bundled catalog has no spectrum for " + tool + "/" + surface);
}

model::modal::ModalModel small_stylus() {
  const double two_pi = 2 * 3.141592653589793;
  return {{two_pi * 92.7, two_pi * 250.0, two_pi * 1457.5},
          {0.36, 0.05, 0.3},
          {23.3, 10.0, 33.1},
          {0.40, 0.30, 5.1}};
}

std::unique_ptr<Voice> catalog_voice(const std::string& tool, const std::string& surface,
                                     double internal_rate, std::uint64_t seed) {
  return build_voice(tool + "/" + surface, small_stylus(), catalog_spectrum(tool, surface),
                     internal_rate, seed);
}

}  // namespace nibrig::rt::testing
