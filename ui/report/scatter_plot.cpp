// write_scatter_plot: labelled points coloured by group over their confidence regions.
#include <cmath>

#include "ui/report/chart_parts.hpp"
#include "ui/report/figures.hpp"
#include "ui/report/scatter_layout.hpp"

namespace nibrig::ui::report {

namespace {

constexpr const char* kScatterPlotKind = "scatter plot";
// Vertices of a drawn ellipse: smooth at any size a figure is likely to give it.
constexpr int ellipse_vertices = 120;
constexpr Rgb leader_grey{150, 150, 150};

}  // namespace

namespace detail {

void validate_scatter(const ScatterPlot& plot, const char* kind) {
  check_size(plot.size, kind, plot.title);
  if (plot.points.empty()) reject(kind, plot.title, "no points to draw");
  for (std::size_t i = 0; i < plot.points.size(); ++i) {
    const auto& p = plot.points[i];
    const std::string name =
        "point " + std::to_string(i) + (p.label.empty() ? "" : " (" + p.label + ")");
    for (const auto& [field, v] : {std::pair{"x", p.x}, {"y", p.y}}) {
      if (!std::isfinite(v)) reject(kind, plot.title, name + " " + field + " is not finite");
    }
    for (std::size_t k = 0; k < p.regions.size(); ++k) {
      const auto& e = p.regions[k];
      const std::string region = name + " region " + std::to_string(k);
      for (const auto& [field, v] : {std::pair{"centre_x", e.centre_x},
                                     {"centre_y", e.centre_y},
                                     {"semi_axis_1", e.semi_axis_1},
                                     {"semi_axis_2", e.semi_axis_2},
                                     {"angle_rad", e.angle_rad}}) {
        if (!std::isfinite(v)) reject(kind, plot.title, region + " " + field + " is not finite");
      }
      for (const auto& [field, v] :
           {std::pair{"semi_axis_1", e.semi_axis_1}, {"semi_axis_2", e.semi_axis_2}}) {
        if (v < 0.0) {
          reject(kind, plot.title,
                 region + " " + field + " = " + std::to_string(v) + " is negative");
        }
      }
      if (!plot.region_labels.empty() && k >= plot.region_labels.size()) {
        reject(kind, plot.title,
               region + " has no legend text: region_labels names " +
                   std::to_string(plot.region_labels.size()) + " styles");
      }
    }
  }
}

namespace {

// The ellipse in data units, mapped vertex by vertex: right on any axes, equal or not.
void region_polygon(const Ellipse& e, const Mapping& m, std::vector<double>& xs,
                    std::vector<double>& ys) {
  ellipse_polygon(e.centre_x, e.centre_y, e.semi_axis_1, e.semi_axis_2, e.angle_rad,
                  ellipse_vertices, xs, ys);
  for (double& x : xs) x = m.px(x);
  for (double& y : ys) y = m.py(y);
}

void draw_regions(PlotPage& page, const ScatterPlot& plot, const ScatterFrame& f) {
  // All fills before any outline, so that no fill hides an outline; the widest style (listed last,
  // e.g. 95 %) first, so that inner regions tint over outer ones.
  std::size_t styles = f.region_outlines.size();
  for (std::size_t k = styles; k-- > 0;) {
    for (std::size_t i = 0; i < plot.points.size(); ++i) {
      if (k >= plot.points[i].regions.size()) continue;
      std::vector<double> xs, ys;
      region_polygon(plot.points[i].regions[k], f.mapping, xs, ys);
      page.colour(f.colours[i], region_alpha);
      page.fill(xs, ys);
    }
  }
  for (std::size_t k = styles; k-- > 0;) {
    page.line_width(f.region_outlines[k].width_px);
    page.dashes(f.region_outlines[k].dashes_px);
    for (std::size_t i = 0; i < plot.points.size(); ++i) {
      if (k >= plot.points[i].regions.size()) continue;
      std::vector<double> xs, ys;
      region_polygon(plot.points[i].regions[k], f.mapping, xs, ys);
      xs.push_back(xs.front()), ys.push_back(ys.front());
      page.colour(f.colours[i]);
      page.polyline(xs, ys);
    }
  }
  page.dashes({});
}

void draw_markers(PlotPage& page, const ScatterPlot& plot, const ScatterFrame& f) {
  const double r = f.marker_radius;
  for (std::size_t i = 0; i < plot.points.size(); ++i) {
    const double x = f.mapping.px(plot.points[i].x), y = f.mapping.py(plot.points[i].y);
    if (plot.points[i].hollow) {
      draw_ring(page, x, y, r, f.colours[i]);
    } else {
      // A thin white rim keeps touching markers apart.
      page.colour({255, 255, 255});
      page.disc(x, y, r + 0.8 * f.style.scale);
      page.colour(f.colours[i]);
      page.disc(x, y, r);
    }
  }
}

void draw_labels(PlotPage& page, const ScatterPlot& plot, const ScatterFrame& f) {
  page.colour(leader_grey);
  page.line_width(0.8 * f.style.scale);
  for (std::size_t i = 0; i < plot.points.size(); ++i) {
    if (!f.labels[i].placed || !f.labels[i].leader) continue;
    const auto l = leader_line(f.label_requests[i], f.labels[i].box, f.marker_radius);
    page.segment(l.x0, l.y0, l.x1, l.y1);
  }
  for (std::size_t i = 0; i < plot.points.size(); ++i) {
    if (!f.labels[i].placed) continue;
    const auto& b = f.labels[i].box;
    // A veil behind the text keeps it legible over region outlines and grid lines.
    page.colour({255, 255, 255}, 0.7);
    page.rectangle(b.x0, b.y0, b.x1, b.y1);
    page.colour(text_grey);
    // The box holds descenders below the capitals: their middle sits a little above its centre.
    const double just = f.labels[i].just;
    page.text(b.x0 + just * b.width(), 0.5 * (b.y0 + b.y1) + 0.12 * f.label_cap, 0.0, just,
              f.label_cap, plot.points[i].label);
  }
}

}  // namespace

void draw_scatter(PlotPage& page, const ScatterPlot& plot, const ScatterFrame& f, const Box& area) {
  const auto& st = f.style;
  draw_grid(page, f.mapping, &f.axes.x, &f.axes.y, st);
  draw_regions(page, plot, f);
  draw_markers(page, plot, f);
  draw_labels(page, plot, f);
  draw_frame(page, f.axes.box, st);
  draw_x_axis(page, f.mapping, f.axes.x, st);
  draw_y_axis(page, f.mapping, f.axes.y, st);
  draw_axis_titles(page, f.axes.box, plot.x_label, plot.y_label, st, area);
  draw_title(page, plot.title, st, area);
  draw_legend(page, f.legend, f.legend_layout, 0.5 * (f.axes.box.x0 + f.axes.box.x1), f.legend_top,
              st);
}

}  // namespace detail

void write_scatter_plot(const ScatterPlot& plot, const std::filesystem::path& png) {
  detail::validate_scatter(plot, kScatterPlotKind);
  const auto f = detail::layout_scatter(plot);
  detail::PlotPage page(plot.title, png, plot.size.width_px, plot.size.height_px);
  detail::draw_scatter(page, plot, f, detail::whole_page(page));
  page.commit();
}

}  // namespace nibrig::ui::report
