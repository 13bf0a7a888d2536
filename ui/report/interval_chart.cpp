// write_interval_chart: one point with its interval per bar, coloured by group, labels turned
// upright under the axis, an optional shaded reference band.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "ui/report/chart_parts.hpp"
#include "ui/report/figures.hpp"

namespace nibrig::ui::report {

namespace {

using namespace detail;

constexpr const char* kIntervalChartKind = "interval chart";
constexpr Rgb band_grey{212, 212, 212};
constexpr Rgb separator_grey{170, 170, 170};

void validate(const IntervalChart& chart) {
  check_size(chart.size, kIntervalChartKind, chart.title);
  if (chart.bars.empty()) reject(kIntervalChartKind, chart.title, "no bars to draw");
  for (std::size_t i = 0; i < chart.bars.size(); ++i) {
    const auto& b = chart.bars[i];
    const std::string name =
        "bar " + std::to_string(i) + (b.label.empty() ? "" : " (" + b.label + ")");
    for (const auto& [field, v] : {std::pair{"value", b.value}, {"low", b.low}, {"high", b.high}}) {
      if (!std::isfinite(v)) reject(kIntervalChartKind, chart.title, name + " " + field + " is not finite");
    }
    // A point outside its own interval can be legitimate (some bootstrap intervals), an interval
    // whose ends are swapped cannot.
    if (b.low > b.high) {
      reject(kIntervalChartKind, chart.title,
             name + " has low " + std::to_string(b.low) + " above high " + std::to_string(b.high));
    }
  }
  if (chart.reference_band) {
    const auto [lo, hi] = *chart.reference_band;
    if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi)) {
      reject(kIntervalChartKind, chart.title,
             "reference band [" + std::to_string(lo) + ", " + std::to_string(hi) +
                 "] is not a finite range with low below high");
    }
  }
}

std::string band_legend(const IntervalChart& chart) {
  if (!chart.reference_label.empty()) return chart.reference_label;
  char text[96];
  std::snprintf(text, sizeof text, "reference %g\u2013%g", chart.reference_band->first,
                chart.reference_band->second);
  return text;
}

}  // namespace

void write_interval_chart(const IntervalChart& chart, const std::filesystem::path& png) {
  validate(chart);
  const auto st = Style::for_size(chart.size);
  const std::size_t n = chart.bars.size();

  std::vector<std::string> groups;
  for (const auto& b : chart.bars) {
    if (!b.group.empty() && std::find(groups.begin(), groups.end(), b.group) == groups.end()) {
      groups.push_back(b.group);
    }
  }
  const auto& palette = categorical_palette();
  const auto colour_of = [&](const std::string& group) {
    const auto it = std::find(groups.begin(), groups.end(), group);
    if (it == groups.end()) return palette[0];
    return palette[static_cast<std::size_t>(it - groups.begin()) % palette.size()];
  };
  std::vector<LegendEntry> legend;
  for (const auto& g : groups) legend.push_back({g, colour_of(g), LegendEntry::Kind::marker});
  if (chart.reference_band)
    legend.push_back({band_legend(chart), band_grey, LegendEntry::Kind::band});

  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& b : chart.bars) {
    lo = std::min({lo, b.low, b.value}), hi = std::max({hi, b.high, b.value});
  }
  if (chart.reference_band) {
    lo = std::min(lo, chart.reference_band->first), hi = std::max(hi, chart.reference_band->second);
  }
  if (hi <= lo) {
    const double half = std::max(std::abs(lo) * 0.1, 0.5);
    lo -= half, hi += half;
  }
  const double pad_y = 0.05 * (hi - lo);
  lo -= pad_y, hi += pad_y;

  // The image grows to give every bar a label's height of room and every label its length.
  const double bar_cap = 0.9 * st.tick_cap;
  const double pitch = 1.6 * bar_cap;
  double longest = 0.0;
  for (const auto& b : chart.bars) longest = std::max(longest, st.text_width(b.label, bar_cap));
  const double y_title = chart.value_label.empty() ? 0.0 : 1.9 * st.label_cap + 0.3 * st.label_gap;
  const double left_guess = st.pad + y_title + 6 * st.tick_cap + st.tick_gap + st.tick_major;
  const double width =
      std::max<double>(chart.size.width_px, std::ceil(left_guess + n * pitch + st.pad));
  const auto legend_layout = layout_legend(legend, width - 2 * st.pad, st);
  const double top = st.pad + title_room(chart.title, st) +
                     (legend.empty() ? 0.0 : legend_layout.height() + 0.5 * st.label_gap) +
                     0.6 * st.tick_cap;
  const double bottom = st.pad + longest + st.tick_gap + st.tick_major;
  // A chart widened for many bars also gets a taller plot, so that it does not become a strip.
  const double plot_height = width > chart.size.width_px
                                 ? std::max(0.4 * chart.size.height_px, 0.28 * width)
                                 : 0.4 * chart.size.height_px;
  const double height =
      std::max<double>(chart.size.height_px, std::ceil(top + bottom + plot_height));

  Box box{0.0, bottom, width - st.pad, height - top};
  const auto value_ticks = linear_ticks(
      lo, hi, box.height(), [&](const std::string&) { return st.tick_cap; }, 4.0 * st.tick_cap);
  box.x0 =
      st.pad + y_title + widest_label(value_ticks, st.tick_cap, st) + st.tick_gap + st.tick_major;
  const Mapping m{box, 0.5, n + 0.5, lo, hi};

  detail::PlotPage page(chart.title, png, static_cast<int>(width), static_cast<int>(height));
  if (chart.reference_band) {
    page.colour(band_grey);
    page.rectangle(box.x0, m.py(chart.reference_band->first), box.x1,
                   m.py(chart.reference_band->second));
  }
  draw_grid(page, m, nullptr, &value_ticks, st);
  // Thin lines between runs of one group, when the bars come grouped.
  page.colour(separator_grey);
  page.line_width(st.grid_width);
  for (std::size_t i = 1; i < n; ++i) {
    if (chart.bars[i].group != chart.bars[i - 1].group) {
      page.segment(m.px(i + 0.5), box.y0, m.px(i + 0.5), box.y1);
    }
  }
  const double cap_half = std::min(0.25 * (m.px(2.0) - m.px(1.0)), 7.0 * st.scale);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& b = chart.bars[i];
    const double x = m.px(i + 1.0);
    page.colour(colour_of(b.group));
    page.line_width(0.8 * st.curve_width);
    page.segment(x, m.py(b.low), x, m.py(b.high));
    page.segment(x - cap_half, m.py(b.low), x + cap_half, m.py(b.low));
    page.segment(x - cap_half, m.py(b.high), x + cap_half, m.py(b.high));
    page.disc(x, m.py(b.value), 4.5 * st.scale);
  }
  draw_frame(page, box, st);
  draw_y_axis(page, m, value_ticks, st);
  page.colour(black);
  page.line_width(st.frame_width);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = m.px(i + 1.0);
    page.segment(x, box.y0, x, box.y0 - st.tick_minor);
  }
  page.colour(text_grey);
  for (std::size_t i = 0; i < n; ++i) {
    // Turned to read upwards, ending just under its tick.
    page.text(m.px(i + 1.0), box.y0 - st.tick_major - st.tick_gap, 90.0, 1.0, bar_cap,
              chart.bars[i].label);
  }
  draw_axis_titles(page, box, "", chart.value_label, st);
  draw_title(page, chart.title, st);
  draw_legend(page, legend, legend_layout, 0.5 * (box.x0 + box.x1),
              height - st.pad - title_room(chart.title, st), st);
  page.commit();
}

}  // namespace nibrig::ui::report
