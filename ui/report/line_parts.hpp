// Pieces shared by the line figures (write_line_plot, write_line_panels): the checks of the curves,
// the range they cover, their colours and legend, and drawing them inside a plot box.
#pragma once

#include <cstddef>
#include <limits>
#include <vector>

#include "ui/report/chart_parts.hpp"
#include "ui/report/figures.hpp"

namespace nibrig::ui::report::detail {

// Curves of at most this many points get a dot on each point.
inline constexpr std::size_t max_points_with_markers = 30;

// Throws std::invalid_argument ("<kind> <title>: ...") for no series, a series without points,
// mismatched lengths, a bad band, or a value that is not finite (or not positive on a log axis).
// The image size is the caller's to check.
void validate_line_series(const LinePlot& plot, const char* kind);

// The data range of one or more plots (y in plot coordinates: log10 on a log axis), widened so
// that no curve or marker touches the frame.
struct LineExtent {
  double x_lo = std::numeric_limits<double>::infinity(), x_hi = -x_lo;
  double y_lo = x_lo, y_hi = -x_lo;
  bool markers = false;
  void add(const LinePlot& plot);
  AxisRange x_range() const;
  AxisRange y_range(bool log_y) const;
};

// Colour of series i: among the curves that are not muted, categorical up to six and an ordered
// colour map beyond; muted ones in shades of grey from dark to light.
Rgb series_colour(const LinePlot& plot, std::size_t i);

// One entry per labelled series.
std::vector<LegendEntry> line_legend(const LinePlot& plot);

// Bands first (so that none hides a curve), then the curves with their markers and error bars.
void draw_curves(PlotPage& page, const LinePlot& plot, const Mapping& m, const Style& st);

// A whole line plot (its title, legend, axes and curves) inside `area` of the page; the plot has
// passed validate_line_series. write_line_plot draws it on a page of its own.
void draw_line_plot(PlotPage& page, const LinePlot& plot, const Box& area, const Style& st);

}  // namespace nibrig::ui::report::detail
