// A small perceptual space for the panel's window tests: three catalog pairings at known places on
// three surfaces, written as a space file the panel opens with --space.
#pragma once

#include <filesystem>

#include "model/io/catalog_file.hpp"
#include "model/space/catalog_descriptors.hpp"
#include "model/space/space_file.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::ui::panel::testing {

inline model::space::SpaceFile small_space() {
  model::space::SpaceFile s;
  s.stimuli = {"cryon/office", "vero1/note", "stab/stone"};
  s.coordinates.resize(2, 3);
  s.coordinates << 0.0, 3.0, -2.0,  //
      0.0, 1.0, 2.0;
  s.model.scale = 2.0 / 3.0;
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

// Eight printed and real tools on office paper placed at their own two descriptors (μ and the
// log10 weighted mean), with the map from descriptors to that space, so that designs can be placed.
inline std::filesystem::path write_descriptor_space(const std::filesystem::path& folder) {
  const auto catalog_file = nibrig::test::assets_dir() / "default_catalog.json";
  const auto catalog = model::io::read_catalog(catalog_file);
  model::space::SpaceFile s;
  s.stimuli = {"vero1/office", "vero2/office", "vero4/office", "DM851/office",
               "DM854/office", "DM951/office", "cryon/office", "stab/office"};
  const auto table = model::space::descriptors_for_stimuli(catalog, catalog_file, s.stimuli, 2);
  s.coordinates = table.values.transpose();
  // A little scatter so that the map's residual covariance is not singular.
  for (Eigen::Index i = 0; i < s.coordinates.cols(); ++i) s.coordinates(0, i) += 0.01 * static_cast<double>(i % 3);
  s.model.scale = 2.0 / 3.0;
  s.descriptor_names = table.names;
  s.descriptors = table.values;
  s.descriptor_source = catalog_file.string();
  s.descriptor_map = model::space::fit_descriptor_map(s.coordinates, table.values, table.names);
  s.judgments = "none: the tools' own descriptors (the panel's tests)";
  std::filesystem::create_directories(folder);
  const auto file = folder / "descriptor_space.json";
  model::space::write_space_file(file, s);
  return file;
}

}  // namespace nibrig::ui::panel::testing
