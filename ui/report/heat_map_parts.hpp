// A heat map drawn into one part of a page, with its colour bar: what write_heat_map draws on a
// page of its own and what figures of several heat maps side by side (the comparison figure) draw
// in each panel.
#pragma once

#include <optional>

#include "ui/report/chart_parts.hpp"
#include "ui/report/figures.hpp"
#include "ui/report/plot_page.hpp"

namespace nibrig::ui::report::detail {

// Throws what write_heat_map documents for bad input; `kind` names the figure in the message.
void validate_heat_map(const HeatMap& map, const char* kind);

// The values the colour scale runs over (linear colour only): values outside are clamped to its
// ends, so that panels sharing one range compare colour for colour.
struct ColourRange {
  double lo, hi;
};

// Draws map's cells, axes, axis titles and colour bar inside `area` (page pixels), leaving `top`
// px free above the plot for a title the caller draws; map.title and map.size are not used.
// Returns the plot box.
Box draw_heat_map(PlotPage& page, const HeatMap& map, const Box& area, double top, const Style& st,
                  std::optional<ColourRange> range = std::nullopt);

}  // namespace nibrig::ui::report::detail
