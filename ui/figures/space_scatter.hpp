// A perceptual space as a scatter plot (Fig. 9, 15): what `nibrig space fit --plot`, the design
// search's path and a stylus's print sheet draw.
#pragma once

#include <string>
#include <vector>

#include "model/space/descriptor_map.hpp"
#include "model/space/space_file.hpp"
#include "ui/report/figures.hpp"

namespace nibrig::ui::figures {

struct PlacedTool {
  std::string name;  // also its label; empty: an unlabelled marker
  model::space::Placement placement;
  std::string group;    // its legend entry; empty: the surface part of the name
  bool regions = true;  // with its 68 % / 95 % ellipses
};

// The first two axes (a 1-D space on a line); judged stimuli as filled points coloured by surface
// (the part of "tool/surface" after the slash; one colour when names have none) with their
// bootstrap regions, placed tools hollow with their 68 % / 95 % prediction ellipses.
report::ScatterPlot space_scatter(const model::space::SpaceFile& space,
                                  const std::vector<PlacedTool>& placed, const std::string& title);

}  // namespace nibrig::ui::figures
