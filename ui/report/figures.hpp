// Publication-quality PNG figures for reports: heat maps (spectrograms), points with intervals,
// line plots and labelled scatter plots with confidence regions. Inputs are plain data so that any
// caller adapts its own types; PLplot's pngcairo device draws them, one figure at a time under a
// process-wide lock, each in a fresh PLplot stream.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace nibrig::ui::report {

// Pixel size of a written PNG. Text, line widths and markers scale with it (relative to the
// default), so a figure keeps its proportions at any resolution.
struct ImageSize {
  int width_px = 1200;
  int height_px = 800;
};

// Text fields (titles, labels, legend entries) are UTF-8 and may use PLplot's text escapes:
// "#gm" is μ, "#u...#d" raises to a superscript, "#d...#u" lowers to a subscript, "##" is a '#'.

// z[iy][ix] is the value of the cell centred on (x[ix], y[iy]). x and y must be strictly increasing
// but need not be uniform: a cell extends half-way to its neighbours (the outer cells as far
// outward as inward). With log_colour the colour shows 20·log10(z / max z) — z an amplitude —
// clamped at -60 dB.
struct HeatMap {
  std::vector<double> x, y;
  std::vector<std::vector<double>> z;
  std::string title, x_label, y_label, colour_label;
  bool log_colour = false;
  ImageSize size{};
};

// A live comparison's spectrograms side by side: measured | simulated | difference (simulated −
// measured). x is time (s) or speed, strictly increasing; y the frequencies (Hz). Values are dB,
// z[iy][ix] as in HeatMap. The first two panels share one colour scale running
// dynamic_range_db down from the louder one's maximum (quieter cells show as its bottom colour), so
// that equal colours are equal levels; the difference has its own scale, symmetric about 0 and
// clamped at ±difference_range_db.
struct ComparisonSpectrograms {
  std::vector<double> x, y;
  std::vector<std::vector<double>> measured_db, simulated_db;
  std::string title, x_label, y_label;
  std::string measured_title = "measured", simulated_title = "simulated",
              difference_title = "simulated - measured";
  double dynamic_range_db = 60.0;
  double difference_range_db = 20.0;
  ImageSize size{2100, 700};
};

// One point estimate with its interval (e.g. μ of a tool–surface pair with its 95 % interval). Bars
// of the same non-empty group share a colour and a legend entry.
struct IntervalBar {
  std::string label;
  double value, low, high;
  std::string group;
};

// The bars are drawn left to right in the given order. size is the smallest image written: it
// widens so that every bar label has room (about 20 px per bar) and heightens for long labels.
struct IntervalChart {
  std::vector<IntervalBar> bars;
  std::string title, value_label;
  std::optional<std::pair<double, double>>
      reference_band;  // drawn as a shaded band with a legend entry
  std::string reference_label;
  ImageSize size{};
};

// One curve; y_low and y_high, if given (both, each as long as x), are drawn as a shaded band.
struct LineSeries {
  std::string label;
  std::vector<double> x, y;
  std::vector<double> y_low, y_high;
  // A reference drawn thin, in grey and under the other curves (e.g. Fig. 14's no-interpolation
  // baselines), so that it does not hide them; several get distinct shades of grey.
  bool muted = false;
};

// Up to six curves (not counting muted ones) get distinct categorical colours; more (spectra at
// many speeds) get an ordered sequence of colours from the heat maps' colour map, in the order
// given. Curves of at most 30 points also get a dot on each point.
struct LinePlot {
  std::vector<LineSeries> series;
  std::string title, x_label, y_label;
  bool log_y = false;
  ImageSize size{};
};

// Small multiples: line plots side by side in rows of `columns`, each with its own axes and its
// title above it (e.g. one panel per speed), under one figure title and one legend — the first
// panel's: give every panel its series in the same order and with the same labels, so that a colour
// means the same in each. With shared_axes every panel covers the range of all of them, so that
// curves compare across panels at a glance; all panels then need the same log_y. Axis titles are
// drawn once per row (y) and under the bottom row (x). A panel's own size is ignored.
struct LinePanels {
  std::vector<LinePlot> panels;
  std::string title;
  int columns = 3;
  bool shared_axes = true;
  ImageSize size{1800, 700};
};

// A region around a point: the ellipse with this centre, semi-axes and the angle (radians, from +x)
// of the first semi-axis.
struct Ellipse {
  double centre_x, centre_y, semi_axis_1, semi_axis_2, angle_rad;
};

// One stimulus of a 2-D space (e.g. a perceptual space), with its confidence regions.
struct ScatterPoint {
  std::string label;  // drawn beside the point unless empty
  double x, y;
  std::string group;             // same non-empty group: same colour and one legend entry
  std::vector<Ellipse> regions;  // regions[k] drawn in style k (see ScatterPlot::region_labels)
  bool hollow = false;           // an open marker (e.g. a tool placed from descriptors, not judged)
};

// Regions are drawn first (pale translucent fills in the point's group colour, then outlines whose
// dash and width say the style k), markers over them, labels last in a small font. Points without
// a group are grey when others have one. Each label goes to the spot beside its point (right, left,
// above, below, the diagonals, then further out with a thin leader line) that covers the fewest
// labels and markers already placed; with more than 40 points a label that cannot be placed
// without covering another label or a marker is left out rather than drawn over the crowd. The axes
// cover every marker and every region's bounding box, with room for each label beside its point.
// The legend has one entry per group, one per region style, and "placed from descriptors" when a
// point is hollow.
struct ScatterPlot {
  std::vector<ScatterPoint> points;
  std::string title, x_label, y_label;
  // Legend text of region style k, e.g. {"68 %", "95 %"}. Empty: regions get no legend entries;
  // otherwise it must name every style a point uses.
  std::vector<std::string> region_labels;
  bool equal_axes = true;  // same scale on x and y (distances in a perceptual space are isotropic)
  // A label that cannot be free of the others is left out, not drawn over them (a print sheet's
  // small plot); so is every such label beyond 40 points. Hollow points (placed tools: what the
  // figure is about) are labelled first and always.
  bool leave_out_crowded_labels = false;
  ImageSize size{};
};

// A page to print beside a fabricated object: a title across the top, a column of text on the
// left (headings and the lines under them, e.g. a stylus's recipe) and the figures on the right,
// the line plot above the scatter plot when there are both. Each figure keeps its own title and
// legend; the page's text sizes are the figures'. A line too long for the column wraps at its
// spaces (a word too long alone is drawn smaller), and the column's text shrinks as a whole when
// there are too many rows for its height.
struct SheetLine {
  std::string text;
  bool heading = false;
};
struct PrintSheet {
  std::string title;
  std::vector<SheetLine> lines;
  std::optional<LinePlot> line_plot;
  std::optional<ScatterPlot> scatter_plot;
  ImageSize size{2000, 1500};
};

// Each writes png through a temporary file in the same folder and a rename, so the path holds
// either its previous content or the complete new figure. Throws std::invalid_argument, naming the
// figure's title and the faulty field, for empty, mismatched or non-finite input (and for a
// scatter plot's negative semi-axes or unnamed region styles);
// std::runtime_error when the PLplot pngcairo device is missing or the file cannot be written. Safe
// to call from several threads.
void write_heat_map(const HeatMap& map, const std::filesystem::path& png);
void write_interval_chart(const IntervalChart& chart, const std::filesystem::path& png);
void write_line_plot(const LinePlot& plot, const std::filesystem::path& png);
void write_line_panels(const LinePanels& figure, const std::filesystem::path& png);
void write_scatter_plot(const ScatterPlot& plot, const std::filesystem::path& png);
void write_print_sheet(const PrintSheet& sheet, const std::filesystem::path& png);
void write_comparison_spectrograms(const ComparisonSpectrograms& figure,
                                   const std::filesystem::path& png);

}  // namespace nibrig::ui::report
