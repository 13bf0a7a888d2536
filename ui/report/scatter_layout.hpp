// Where everything of a scatter plot goes before anything is drawn: colours per group, legend,
// axis ranges that hold every marker, region and label (one data unit as many pixels on x as on y
// when asked), and the labels' spots. Apart from the drawing so that tests can find a point's
// pixel.
#pragma once

#include <vector>

#include "ui/report/chart_parts.hpp"
#include "ui/report/figures.hpp"
#include "ui/report/label_placement.hpp"

namespace nibrig::ui::report::detail {

// Beyond this many points a label that would cover another label or a marker is left out.
constexpr std::size_t max_points_all_labelled = 40;

struct ScatterFrame {
  Style style;
  std::vector<Rgb> colours;  // of each point
  std::vector<LegendEntry> legend;
  LegendLayout legend_layout;
  double legend_top = 0.0;  // page y of the legend's first row
  AxesLayout axes;
  Mapping mapping;                     // data to page pixels (origin bottom left)
  std::vector<LineStyle> region_outlines;  // style k of the regions
  double marker_radius = 0.0, label_cap = 0.0;
  PlacementOptions placement{};
  std::vector<LabelRequest> label_requests;  // of each point, page pixels
  std::vector<PlacedLabel> labels;           // of each point
};

// The outline of region style k: the first solid and heaviest, then dashed, dotted, dash-dotted.
LineStyle region_outline(std::size_t k, const Style& st);

// Half-extents along x and y of an ellipse's bounding box.
std::pair<double, double> ellipse_half_extents(const Ellipse& e);

// Lays out a plot that has passed validate_scatter (finite values, at least one point): on a page
// of its own, or inside `area` of a page with the page's style (a print sheet's part).
ScatterFrame layout_scatter(const ScatterPlot& plot);
ScatterFrame layout_scatter(const ScatterPlot& plot, const Style& style, const Box& area);

// Throws std::invalid_argument ("<kind> <title>: ...") as write_scatter_plot does.
void validate_scatter(const ScatterPlot& plot, const char* kind);
// Everything of a laid-out plot: regions, markers, labels, axes, its title (on `area`) and legend.
void draw_scatter(PlotPage& page, const ScatterPlot& plot, const ScatterFrame& f, const Box& area);

}  // namespace nibrig::ui::report::detail
