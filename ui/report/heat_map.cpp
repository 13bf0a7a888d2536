// write_heat_map: a spectrogram-style image of z over non-uniform x and y, with a colour bar.
#include <algorithm>
#include <cmath>
#include <limits>

#include "ui/report/chart_parts.hpp"
#include "ui/report/figures.hpp"
#include "ui/report/heat_map_parts.hpp"

namespace nibrig::ui::report {

namespace detail {

namespace {

constexpr double floor_db = -60.0;

void check_axis(const HeatMap& map, const std::vector<double>& v, const char* name,
                const char* kind) {
  if (v.empty()) reject(kind, map.title, std::string(name) + " is empty");
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!std::isfinite(v[i])) {
      reject(kind, map.title, std::string(name) + "[" + std::to_string(i) + "] is not finite");
    }
    if (i > 0 && !(v[i] > v[i - 1])) {
      reject(kind, map.title,
             std::string(name) + " is not strictly increasing at index " + std::to_string(i) +
                 " (" + std::to_string(v[i - 1]) + " then " + std::to_string(v[i]) + ")");
    }
  }
}

}  // namespace

void validate_heat_map(const HeatMap& map, const char* kind) {
  check_size(map.size, kind, map.title);
  check_axis(map, map.x, "x", kind);
  check_axis(map, map.y, "y", kind);
  if (map.z.size() != map.y.size()) {
    reject(kind, map.title,
           "z has " + std::to_string(map.z.size()) + " rows but y has " +
               std::to_string(map.y.size()) + " values (z is indexed z[iy][ix])");
  }
  bool any_positive = false;
  for (std::size_t j = 0; j < map.z.size(); ++j) {
    if (map.z[j].size() != map.x.size()) {
      reject(kind, map.title,
             "z row " + std::to_string(j) + " has " + std::to_string(map.z[j].size()) +
                 " values but x has " + std::to_string(map.x.size()));
    }
    for (std::size_t i = 0; i < map.z[j].size(); ++i) {
      const double v = map.z[j][i];
      const std::string where = "z[" + std::to_string(j) + "][" + std::to_string(i) + "]";
      if (!std::isfinite(v)) reject(kind, map.title, where + " is not finite");
      if (map.log_colour && v < 0.0) {
        reject(kind, map.title,
               where + " = " + std::to_string(v) +
                   " is negative, which a dB colour scale cannot show");
      }
      any_positive = any_positive || v > 0.0;
    }
  }
  if (map.log_colour && !any_positive) {
    reject(kind, map.title, "a dB colour scale needs at least one positive z, and all are zero");
  }
}

namespace {

// Cell edges half-way between centres; the outer cells as wide outward as inward.
std::vector<double> edges_of(const std::vector<double>& centres) {
  const std::size_t n = centres.size();
  std::vector<double> e(n + 1);
  if (n == 1) {
    const double half = std::max(std::abs(centres[0]) * 0.05, 0.5);
    return {centres[0] - half, centres[0] + half};
  }
  for (std::size_t i = 1; i < n; ++i) e[i] = 0.5 * (centres[i - 1] + centres[i]);
  e[0] = centres[0] - (e[1] - centres[0]);
  e[n] = centres[n - 1] + (centres[n - 1] - e[n - 1]);
  return e;
}

// With more cells than pixels along an axis, neighbouring cells merge (keeping the largest value,
// so that narrow spectral lines stay visible) until each is at least about a pixel wide.
void merge_columns(std::vector<double>& edges, std::vector<std::vector<double>>& t, double pixels) {
  const std::size_t n = edges.size() - 1;
  const auto group = static_cast<std::size_t>(std::ceil(n / std::max(pixels, 1.0)));
  if (group <= 1) return;
  std::vector<double> merged_edges;
  for (std::size_t i = 0; i < n; i += group) merged_edges.push_back(edges[i]);
  merged_edges.push_back(edges[n]);
  for (auto& row : t) {
    std::vector<double> merged;
    for (std::size_t i = 0; i < n; i += group) {
      merged.push_back(
          *std::max_element(row.begin() + static_cast<std::ptrdiff_t>(i),
                            row.begin() + static_cast<std::ptrdiff_t>(std::min(n, i + group))));
    }
    row = std::move(merged);
  }
  edges = std::move(merged_edges);
}

void merge_rows(std::vector<double>& edges, std::vector<std::vector<double>>& t, double pixels) {
  // Rows merge like columns of the transposed image.
  const std::size_t ny = t.size(), nx = t.front().size();
  std::vector<std::vector<double>> transposed(nx, std::vector<double>(ny));
  for (std::size_t j = 0; j < ny; ++j) {
    for (std::size_t i = 0; i < nx; ++i) transposed[i][j] = t[j][i];
  }
  merge_columns(edges, transposed, pixels);
  const std::size_t merged = transposed.front().size();
  t.assign(merged, std::vector<double>(nx));
  for (std::size_t j = 0; j < merged; ++j) {
    for (std::size_t i = 0; i < nx; ++i) t[j][i] = transposed[i][j];
  }
}

}  // namespace

Box draw_heat_map(PlotPage& page, const HeatMap& map, const Box& area, double top_room,
                  const Style& st, std::optional<ColourRange> range) {
  const double width = area.width(), height = area.height();

  // Colour coordinate t in [0, 1] of every cell, and the range the colour bar shows.
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& row : map.z) {
    for (double v : row) lo = std::min(lo, v), hi = std::max(hi, v);
  }
  std::vector<std::vector<double>> t = map.z;
  if (map.log_colour) {
    const double max = hi;
    for (auto& row : t) {
      for (double& v : row) {
        const double db = v > 0.0 ? 20.0 * std::log10(v / max) : floor_db;
        v = (std::max(db, floor_db) - floor_db) / -floor_db;
      }
    }
    lo = floor_db;
    hi = 0.0;
  } else {
    if (range) {
      lo = range->lo;
      hi = range->hi;
    }
    if (hi <= lo) {  // a constant field: centre it in a range around its value
      const double half = std::max(std::abs(lo) * 0.1, 0.5);
      lo -= half;
      hi += half;
    }
    for (auto& row : t) {
      for (double& v : row) v = std::clamp((v - lo) / (hi - lo), 0.0, 1.0);
    }
  }
  auto x_edges = edges_of(map.x);
  auto y_edges = edges_of(map.y);

  // The colour bar: a strip right of the plot, its ticks and labels, and its title turned upwards.
  const double bar_gap = 22 * st.scale, bar_width = 26 * st.scale;
  const double rough_height = height - st.pad - top_room - 4 * st.label_cap;
  const auto bar_ticks_rough = linear_ticks(
      lo, hi, rough_height, [&](const std::string&) { return st.tick_cap; }, 4.0 * st.tick_cap);
  const double bar_labels = widest_label(bar_ticks_rough, st.tick_cap, st);
  const double right = bar_gap + bar_width + st.tick_major + st.tick_gap + bar_labels +
                       (map.colour_label.empty() ? 0.0 : 0.5 * st.label_gap + 1.9 * st.label_cap) +
                       st.pad;
  auto axes = layout_axes(st, width, height, top_room, map.x_label, map.y_label, right,
                          {x_edges.front(), x_edges.back()}, {y_edges.front(), y_edges.back()});
  axes.box = Box{axes.box.x0 + area.x0, axes.box.y0 + area.y0, axes.box.x1 + area.x0,
                 axes.box.y1 + area.y0};
  const Mapping m{axes.box, x_edges.front(), x_edges.back(), y_edges.front(), y_edges.back()};

  merge_columns(x_edges, t, axes.box.width());
  merge_rows(y_edges, t, axes.box.height());

  page.cells(axes.box.x0, axes.box.y0, axes.box.x1, axes.box.y1, x_edges, y_edges, t);
  draw_frame(page, axes.box, st);
  draw_x_axis(page, m, axes.x, st);
  draw_y_axis(page, m, axes.y, st);
  draw_axis_titles(page, axes.box, map.x_label, map.y_label, st, area);

  const Box bar{axes.box.x1 + bar_gap, axes.box.y0, axes.box.x1 + bar_gap + bar_width, axes.box.y1};
  constexpr int steps = 256;  // one row per colour-map entry
  std::vector<double> bar_y(steps + 1);
  std::vector<std::vector<double>> gradient(steps, std::vector<double>(1));
  for (int k = 0; k <= steps; ++k) bar_y[k] = static_cast<double>(k) / steps;
  for (int k = 0; k < steps; ++k) gradient[k][0] = (k + 0.5) / steps;
  page.cells(bar.x0, bar.y0, bar.x1, bar.y1, {0.0, 1.0}, bar_y, gradient);
  draw_frame(page, bar, st);
  const Mapping bar_map{bar, 0.0, 1.0, lo, hi};
  auto bar_ticks = linear_ticks(
      lo, hi, bar.height(), [&](const std::string&) { return st.tick_cap; }, 4.0 * st.tick_cap);
  bar_ticks.minor.clear();  // on a colour scale, minor ticks are clutter
  draw_y_axis(page, bar_map, bar_ticks, st, true);
  if (!map.colour_label.empty()) {
    page.colour(black);
    const double x = bar.x1 + st.tick_major + st.tick_gap +
                     widest_label(bar_ticks, st.tick_cap, st) + 0.5 * st.label_gap +
                     0.75 * st.label_cap;
    page.text(x, 0.5 * (bar.y0 + bar.y1), 90.0, 0.5,
              st.fit(map.colour_label, st.label_cap, bar.height() + st.pad), map.colour_label);
  }
  return axes.box;
}

}  // namespace detail

void write_heat_map(const HeatMap& map, const std::filesystem::path& png) {
  detail::validate_heat_map(map, "heat map");
  const auto st = detail::Style::for_size(map.size);
  const double width = map.size.width_px, height = map.size.height_px;
  detail::PlotPage page(map.title, png, map.size.width_px, map.size.height_px);
  detail::draw_heat_map(page, map, detail::Box{0.0, 0.0, width, height},
                        st.pad + detail::title_room(map.title, st), st);
  detail::draw_title(page, map.title, st);
  page.commit();
}

}  // namespace nibrig::ui::report
