#include "ui/report/line_parts.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace nibrig::ui::report::detail {

namespace {

// Beyond this many curves, hues stop being told apart at a glance and an ordered map reads better.
constexpr std::size_t max_categorical = 6;

// A range that is not empty: a single value gets some room around it.
AxisRange widen(double lo, double hi, double pad_fraction, bool log) {
  if (hi - lo <= 0.0) {
    const double half = log ? 0.5 : std::max(std::abs(lo) * 0.1, 0.5);
    return {lo - half, hi + half, log};
  }
  const double pad = (hi - lo) * pad_fraction;
  return {lo - pad, hi + pad, log};
}

}  // namespace

Rgb series_colour(const LinePlot& plot, std::size_t i) {
  const bool muted = plot.series[i].muted;
  std::size_t rank = 0, n = 0;  // i's place among the series of its kind, and how many there are
  for (std::size_t k = 0; k < plot.series.size(); ++k) {
    if (plot.series[k].muted != muted) continue;
    if (k < i) ++rank;
    ++n;
  }
  if (muted) {
    const int grey =
        n == 1
            ? 140
            : 95 + static_cast<int>(100 * static_cast<double>(rank) / static_cast<double>(n - 1));
    return Rgb{grey, grey, grey};
  }
  if (n <= max_categorical) return categorical_palette()[rank];
  // Many curves are usually an ordered family (spectra at increasing speeds): an ordered map, its
  // top end left out because pale yellow vanishes on white.
  return viridis_at(0.88 * static_cast<double>(rank) / static_cast<double>(n - 1));
}

void validate_line_series(const LinePlot& plot, const char* kind) {
  if (plot.series.empty()) reject(kind, plot.title, "no series to draw");
  for (std::size_t s = 0; s < plot.series.size(); ++s) {
    const auto& series = plot.series[s];
    const std::string name = "series " + std::to_string(s) +
                             (series.label.empty() ? std::string() : " (" + series.label + ")");
    if (series.x.empty()) reject(kind, plot.title, name + " has no points");
    if (series.y.size() != series.x.size()) {
      reject(kind, plot.title,
             name + " has " + std::to_string(series.x.size()) + " x but " +
                 std::to_string(series.y.size()) + " y values");
    }
    const bool band = !series.y_low.empty() || !series.y_high.empty();
    if (band &&
        (series.y_low.size() != series.x.size() || series.y_high.size() != series.x.size())) {
      reject(kind, plot.title,
             name + " has a band of " + std::to_string(series.y_low.size()) + " low and " +
                 std::to_string(series.y_high.size()) + " high values for " +
                 std::to_string(series.x.size()) + " points");
    }
    const auto check = [&](const std::vector<double>& v, const char* field, bool positive) {
      for (std::size_t i = 0; i < v.size(); ++i) {
        if (!std::isfinite(v[i])) {
          reject(kind, plot.title,
                 name + " " + field + "[" + std::to_string(i) + "] is not finite");
        }
        if (positive && v[i] <= 0.0) {
          reject(kind, plot.title,
                 name + " " + field + "[" + std::to_string(i) + "] = " + std::to_string(v[i]) +
                     " cannot be shown on a log axis");
        }
      }
    };
    check(series.x, "x", false);
    check(series.y, "y", plot.log_y);
    check(series.y_low, "y_low", plot.log_y);
    check(series.y_high, "y_high", plot.log_y);
    for (std::size_t i = 0; band && i < series.x.size(); ++i) {
      if (series.y_low[i] > series.y_high[i]) {
        reject(kind, plot.title,
               name + " band at point " + std::to_string(i) + " has y_low " +
                   std::to_string(series.y_low[i]) + " above y_high " +
                   std::to_string(series.y_high[i]));
      }
    }
  }
}

void LineExtent::add(const LinePlot& plot) {
  const auto yv = [&](double y) { return plot.log_y ? std::log10(y) : y; };
  for (const auto& s : plot.series) {
    for (double x : s.x) x_lo = std::min(x_lo, x), x_hi = std::max(x_hi, x);
    for (const auto* v : {&s.y, &s.y_low, &s.y_high}) {
      for (double y : *v) y_lo = std::min(y_lo, yv(y)), y_hi = std::max(y_hi, yv(y));
    }
    markers = markers || s.x.size() <= max_points_with_markers;
  }
}

AxisRange LineExtent::x_range() const { return widen(x_lo, x_hi, markers ? 0.03 : 0.0, false); }

AxisRange LineExtent::y_range(bool log_y) const { return widen(y_lo, y_hi, 0.05, log_y); }

std::vector<LegendEntry> line_legend(const LinePlot& plot) {
  std::vector<LegendEntry> legend;
  for (std::size_t i = 0; i < plot.series.size(); ++i) {
    const auto& s = plot.series[i];
    if (s.label.empty()) continue;
    legend.push_back({s.label, series_colour(plot, i), LegendEntry::Kind::line,
                      s.x.size() <= max_points_with_markers, !s.y_low.empty()});
  }
  return legend;
}

void draw_curves(PlotPage& page, const LinePlot& plot, const Mapping& m, const Style& st) {
  const auto yv = [&](double y) { return plot.log_y ? std::log10(y) : y; };
  for (std::size_t i = 0; i < plot.series.size(); ++i) {
    const auto& s = plot.series[i];
    if (s.y_low.empty()) continue;
    page.colour(series_colour(plot, i), band_alpha);
    if (s.x.size() == 1) continue;  // a single point's interval is drawn as an error bar below
    std::vector<double> px, py;
    for (std::size_t k = 0; k < s.x.size(); ++k)
      px.push_back(m.px(s.x[k])), py.push_back(m.py(yv(s.y_high[k])));
    for (std::size_t k = s.x.size(); k-- > 0;)
      px.push_back(m.px(s.x[k])), py.push_back(m.py(yv(s.y_low[k])));
    page.fill(px, py);
  }
  // Muted references first, so that the curves they are compared with lie on top.
  std::vector<std::size_t> order;
  for (bool muted : {true, false})
    for (std::size_t i = 0; i < plot.series.size(); ++i)
      if (plot.series[i].muted == muted) order.push_back(i);
  std::size_t coloured = 0;
  for (const auto& s : plot.series) coloured += !s.muted;
  for (std::size_t i : order) {
    const auto& s = plot.series[i];
    const auto c = series_colour(plot, i);
    page.colour(c);
    const double width = coloured > max_categorical ? 0.75 * st.curve_width : st.curve_width;
    page.line_width(s.muted ? 0.6 * width : width);
    std::vector<double> px, py;
    for (std::size_t k = 0; k < s.x.size(); ++k)
      px.push_back(m.px(s.x[k])), py.push_back(m.py(yv(s.y[k])));
    page.polyline(px, py);
    if (s.x.size() <= max_points_with_markers) {
      for (std::size_t k = 0; k < px.size(); ++k) page.disc(px[k], py[k], 4.5 * st.scale);
    }
    if (s.x.size() == 1 && !s.y_low.empty()) {
      page.line_width(st.curve_width);
      page.segment(px[0], m.py(yv(s.y_low[0])), px[0], m.py(yv(s.y_high[0])));
    }
  }
}

}  // namespace nibrig::ui::report::detail
