// Figures of perceptual spaces: the space with its bootstrap regions and tools placed from
// descriptors (Fig. 9, 15), and the cross-validated error of the dimension × λ sweep (Fig. 8).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "model/space/descriptor_map.hpp"
#include "model/space/dimension_sweep.hpp"
#include "model/space/space_file.hpp"

namespace nibrig::ui::cli {

struct PlacedTool {
  std::string name;  // also its label; empty: an unlabelled marker
  model::space::Placement placement;
  std::string group;    // its legend entry; empty: the surface part of the name
  bool regions = true;  // with its 68 % / 95 % ellipses
};

// The first two axes (a 1-D space on a line); judged stimuli as filled points coloured by surface
// (the part of "tool/surface" after the slash; one colour when names have none) with their
// bootstrap regions, placed tools hollow with their 68 % / 95 % prediction ellipses.
void write_space_plot(const model::space::SpaceFile& space, const std::vector<PlacedTool>& placed,
                      const std::string& title, const std::filesystem::path& png);

// Error against λ, one curve per dimension (against dimensions when only one λ was swept).
void write_sweep_plot(const std::vector<model::space::SweepPoint>& points, const std::string& title,
                      const std::filesystem::path& png);

}  // namespace nibrig::ui::cli
