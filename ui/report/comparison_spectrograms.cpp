// write_comparison_spectrograms: three heat-map panels (measured, simulated, their difference) on
// one page, drawn by the heat map's own panel code.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "ui/report/chart_parts.hpp"
#include "ui/report/figures.hpp"
#include "ui/report/heat_map_parts.hpp"

namespace nibrig::ui::report {

namespace {

using namespace detail;

constexpr const char* kSpectrogramsKind = "comparison spectrograms";

HeatMap panel(const ComparisonSpectrograms& f, std::vector<std::vector<double>> z,
              const std::string& title, const std::string& colour_label, bool y_label) {
  HeatMap map;
  map.x = f.x;
  map.y = f.y;
  map.z = std::move(z);
  map.title = title;
  map.x_label = f.x_label;
  // The frequency axis is the same in all three: titled once, on the left.
  map.y_label = y_label ? f.y_label : std::string();
  map.colour_label = colour_label;
  map.size = f.size;
  return map;
}

}  // namespace

void write_comparison_spectrograms(const ComparisonSpectrograms& figure,
                                   const std::filesystem::path& png) {
  if (!(figure.dynamic_range_db > 0) || !std::isfinite(figure.dynamic_range_db))
    reject(kSpectrogramsKind, figure.title, "dynamic_range_db must be positive and finite");
  if (!(figure.difference_range_db > 0) || !std::isfinite(figure.difference_range_db))
    reject(kSpectrogramsKind, figure.title, "difference_range_db must be positive and finite");
  HeatMap measured = panel(figure, figure.measured_db, figure.measured_title, "dB", true);
  HeatMap simulated = panel(figure, figure.simulated_db, figure.simulated_title, "dB", false);
  // Each checked as a heat map of its own under the figure's title, the message naming the panel;
  // equal grids then follow from both matching x and y.
  for (const HeatMap* map : {&measured, &simulated}) {
    HeatMap named = *map;
    named.title = figure.title;
    validate_heat_map(named, (std::string(kSpectrogramsKind) + ", " + map->title + " panel,").c_str());
  }
  std::vector<std::vector<double>> difference = figure.simulated_db;
  double top = -std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < difference.size(); ++j) {
    for (std::size_t i = 0; i < difference[j].size(); ++i) {
      top = std::max({top, figure.measured_db[j][i], figure.simulated_db[j][i]});
      difference[j][i] -= figure.measured_db[j][i];
    }
  }
  HeatMap diff = panel(figure, std::move(difference), figure.difference_title, "dB", false);

  const auto st = Style::for_size(figure.size);
  const double width = figure.size.width_px, height = figure.size.height_px;
  const double top_room = st.pad + title_room(figure.title, st);
  const double panel_title_room = 1.8 * st.label_cap;
  const double panel_width = width / 3.0;
  PlotPage page(figure.title, png, figure.size.width_px, figure.size.height_px);
  const HeatMap* maps[3] = {&measured, &simulated, &diff};
  const ColourRange ranges[3] = {{top - figure.dynamic_range_db, top},
                                 {top - figure.dynamic_range_db, top},
                                 {-figure.difference_range_db, figure.difference_range_db}};
  for (int k = 0; k < 3; ++k) {
    const Box area{k * panel_width, 0.0, (k + 1) * panel_width, height - top_room};
    const Box box = draw_heat_map(page, *maps[k], area, panel_title_room, st, ranges[k]);
    page.colour(black);
    page.text(0.5 * (box.x0 + box.x1), area.y1 - 0.8 * st.label_cap, 0.0, 0.5,
              st.fit(maps[k]->title, st.label_cap, area.width() - 2 * st.pad), maps[k]->title);
  }
  draw_title(page, figure.title, st);
  page.commit();
}

}  // namespace nibrig::ui::report
