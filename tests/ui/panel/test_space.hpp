// A small perceptual space for the panel's window tests: three catalog pairings at known places on
// three surfaces, written as a space file the panel opens with --space.
#pragma once

#include <filesystem>

#include "model/space/space_file.hpp"

namespace nibrig::ui::panel::testing {

inline model::space::SpaceFile small_space() {
  model::space::SpaceFile s;
  s.stimuli = {"cryon/office", "vero1/note", "stab/stone"};
  s.coordinates.resize(2, 3);
  s.coordinates << 0.0, 3.0, -2.0,  //
      0.0, 1.0, 2.0;
  s.scale = 2.0 / 3.0;
  s.lambda = 1.0;
  s.judgments = "written by the panel's tests";
  return s;
}

inline std::filesystem::path write_small_space(const std::filesystem::path& folder) {
  std::filesystem::create_directories(folder);
  const auto file = folder / "space.json";
  model::space::write_space_file(file, small_space());
  return file;
}

}  // namespace nibrig::ui::panel::testing
