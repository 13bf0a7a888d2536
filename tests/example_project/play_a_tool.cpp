// Plays a tool of a catalog through nibrig's engine, as an application of one's own would: the
// pairing's measured vibration A(f, v) on a small stylus, one sweep of the paper's speeds (3 s),
// rendered in 64-frame blocks as an audio callback would be. Prints the output's RMS and peak.
//   play_a_tool <catalog.json> <tool id> <surface id>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "model/io/catalog_file.hpp"
#include "rt/engine.hpp"
#include "rt/voice_builder.hpp"

int main(int argc, char** argv) try {
  if (argc != 4) {
    std::fprintf(stderr, "usage: play_a_tool <catalog.json> <tool id> <surface id>\n");
    return 2;
  }
  const auto catalog = nibrig::model::io::read_catalog(argv[1]);
  const auto pairing = std::find_if(catalog.pairings.begin(), catalog.pairings.end(), [&](auto& p) {
    return p.tool == argv[2] && p.surface == argv[3] && p.vibration;
  });
  if (pairing == catalog.pairings.end()) {
    std::fprintf(stderr, "play_a_tool: %s has no vibration for %s on %s\n", argv[1], argv[2],
                 argv[3]);
    return 1;
  }
  // A stylus of three modes at 200, 900 and 3000 Hz with the paper's stiffness damping.
  nibrig::model::modal::ModalModel stylus;
  for (double hz : {200.0, 900.0, 3000.0}) {
    const double omega = 2 * std::numbers::pi * hz;
    stylus.omega.push_back(omega);
    stylus.zeta.push_back(nibrig::model::modal::rayleigh_damping_ratio(omega, 0.0, 1.25e-3));
    stylus.input.push_back(1.0);
    stylus.output.push_back(1.0);
  }
  nibrig::rt::Engine engine{nibrig::rt::EngineSettings{}};
  engine.load(0, nibrig::rt::build_voice(std::string(argv[2]) + " on " + argv[3], stylus,
                                         pairing->vibration->spectrum, engine.internal_rate(), 1));
  engine.select(0);
  engine.attach(std::make_unique<nibrig::rt::SweepStroke>());
  std::vector<float> block(64);
  double sum = 0, peak = 0;
  const std::size_t blocks = 3 * 48000 / block.size();
  for (std::size_t b = 0; b < blocks; ++b) {
    engine.render(block.data(), block.size());
    for (float x : block) {
      sum += static_cast<double>(x) * x;
      peak = std::max(peak, std::abs(static_cast<double>(x)));
    }
  }
  std::printf("{\"frames\": %zu, \"rms\": %.12g, \"peak\": %.12g}\n", blocks * block.size(),
              std::sqrt(sum / static_cast<double>(blocks * block.size())), peak);
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "play_a_tool: %s\n", e.what());
  return 1;
}
