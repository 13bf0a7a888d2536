// Pieces shared by the report figures: sizes that scale with the image, the mapping from data to
// page pixels, axes with outward ticks and labels, titles, legends, and input validation.
#pragma once

#include <string>
#include <vector>

#include "ui/report/axis_ticks.hpp"
#include "ui/report/colour_maps.hpp"
#include "ui/report/figures.hpp"
#include "ui/report/plot_page.hpp"

namespace nibrig::ui::report::detail {

// Lengths in page pixels for one image. At the default 1200×800 the tick labels are 15 px capitals
// (about 21 px type): legible when the figure is shrunk to a paper's column width.
struct Style {
  double scale;
  double pad, tick_major, tick_minor, tick_gap, label_gap;
  double tick_cap, label_cap, title_cap, legend_cap;
  double frame_width, curve_width, grid_width;

  static Style for_size(const ImageSize& size);
  double text_width(const std::string& text, double cap) const {
    return text_width_caps(text) * cap;
  }
  // The cap height at which text fits in `room` px: `cap`, or smaller for a very long text.
  double fit(const std::string& text, double cap, double room) const;
};

struct Box {
  double x0, y0, x1, y1;  // page pixels, origin bottom left
  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
};

// Data coordinates (the logarithm already taken on log axes) to page pixels inside a box.
struct Mapping {
  Box box;
  double xmin, xmax, ymin, ymax;
  double px(double x) const { return box.x0 + (x - xmin) / (xmax - xmin) * box.width(); }
  double py(double y) const { return box.y0 + (y - ymin) / (ymax - ymin) * box.height(); }
};

constexpr Rgb black{0, 0, 0};
constexpr Rgb text_grey{40, 40, 40};
constexpr Rgb grid_grey{225, 225, 225};

// Vertical room (px) that tick labels under an x axis take, ticks included.
double x_tick_room(const Style& st);
// Widest label of a set of ticks, px.
double widest_label(const AxisTicks& ticks, double cap, const Style& st);

// Light lines across the box at the major ticks (either may be null).
void draw_grid(PlotPage& page, const Mapping& m, const AxisTicks* x, const AxisTicks* y,
               const Style& st);
void draw_frame(PlotPage& page, const Box& box, const Style& st);
// Outward ticks with labels: under the box, left of it, or right of it.
void draw_x_axis(PlotPage& page, const Mapping& m, const AxisTicks& ticks, const Style& st);
void draw_y_axis(PlotPage& page, const Mapping& m, const AxisTicks& ticks, const Style& st,
                 bool right_side = false);

// Where the plot box goes and which ticks its axes get, for an image of width × height with `top`
// px reserved above the box (title, legend), and room for axis titles when they are not empty.
// right_reserved is the room kept right of the box (a colour bar), at least the padding.
struct AxesLayout {
  Box box;
  AxisTicks x, y;
};
struct AxisRange {
  double lo, hi;  // plot coordinates (log10 of the values on a log axis)
  bool log = false;
};
AxesLayout layout_axes(const Style& st, double width, double height, double top,
                       const std::string& x_label, const std::string& y_label,
                       double right_reserved, AxisRange x, AxisRange y);
// The same inside `area` of a page (a panel of several, a part of a print sheet).
AxesLayout layout_axes(const Style& st, const Box& area, double top, const std::string& x_label,
                       const std::string& y_label, double right_reserved, AxisRange x,
                       AxisRange y);
// Axis titles: centred under the box, and turned to read upwards at the left edge of the image —
// or of `area`, the part of the image the plot owns (a panel of several).
void draw_axis_titles(PlotPage& page, const Box& box, const std::string& x_label,
                      const std::string& y_label, const Style& st);
void draw_axis_titles(PlotPage& page, const Box& box, const std::string& x_label,
                      const std::string& y_label, const Style& st, const Box& area);
// The figure title, centred on the image at its top, or on `area` at its top (a figure drawn in a
// part of a page, e.g. a print sheet's).
double title_room(const std::string& title, const Style& st);
void draw_title(PlotPage& page, const std::string& title, const Style& st);
void draw_title(PlotPage& page, const std::string& title, const Style& st, const Box& area);
Box whole_page(const PlotPage& page);

// How a line is drawn: its width and, if not solid, alternating dash and gap lengths (px).
struct LineStyle {
  double width_px = 1.0;
  std::vector<double> dashes_px;
};

// An ellipse (centre, semi-axes, angle of the first semi-axis from +x in radians) as n vertices
// of a polygon (the first not repeated at the end), appended to xs and ys.
void ellipse_polygon(double cx, double cy, double a, double b, double angle_rad, int n,
                     std::vector<double>& xs, std::vector<double>& ys);

// The fill of a region: its colour at this opacity, a pale tint on white, so that regions which
// overlap stay visible through one another.
constexpr double region_alpha = 0.10;

// An open marker: a ring in `colour` of outer radius `radius`, white inside.
void draw_ring(PlotPage& page, double x, double y, double radius, Rgb colour);

struct LegendEntry {
  // marker: a dot on an upright bar (a point with its interval); point: a dot alone; open_point: a
  // ring; region: a small ellipse, pale inside, outlined with `outline`.
  enum class Kind { line, marker, band, point, open_point, region };
  std::string label;
  Rgb colour;
  Kind kind;
  bool with_marker = false;  // a line with a dot on it
  bool with_band = false;    // a line over its shaded band
  LineStyle outline{};       // region outlines only
};

struct LegendLayout {
  int columns = 0, rows = 0;
  double column_width = 0, row_height = 0;
  double height() const { return rows * row_height; }
};

LegendLayout layout_legend(const std::vector<LegendEntry>& entries, double available_width,
                           const Style& st);
// Rows of entries centred on centre_x, the first row's top at top_y.
void draw_legend(PlotPage& page, const std::vector<LegendEntry>& entries,
                 const LegendLayout& layout, double centre_x, double top_y, const Style& st);

// The band colour: a light, translucent version of c.
constexpr double band_alpha = 0.22;

// A name for error messages: the title in quotes, or "(untitled)".
std::string quoted_title(const std::string& title);

// Throws std::invalid_argument("<kind> <title>: <what>").
[[noreturn]] void reject(const std::string& kind, const std::string& title,
                         const std::string& what);

// Checks an ImageSize: each side 64 to 20000 px.
void check_size(const ImageSize& size, const std::string& kind, const std::string& title);

}  // namespace nibrig::ui::report::detail
