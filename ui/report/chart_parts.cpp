#include "ui/report/chart_parts.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace nibrig::ui::report::detail {

Style Style::for_size(const ImageSize& size) {
  const double s = std::clamp(std::sqrt(size.width_px / 1200.0 * size.height_px / 800.0), 0.6, 4.0);
  Style st{};
  st.scale = s;
  st.pad = 16 * s;
  st.tick_major = 9 * s;
  st.tick_minor = 5 * s;
  st.tick_gap = 7 * s;
  st.label_gap = 14 * s;
  st.tick_cap = 15 * s;
  st.label_cap = 17 * s;
  st.title_cap = 19 * s;
  st.legend_cap = 15 * s;
  st.frame_width = 1.6 * s;
  st.curve_width = 2.6 * s;
  st.grid_width = 1.0 * s;
  return st;
}

double Style::fit(const std::string& text, double cap, double room) const {
  const double width = text_width(text, cap);
  return width <= room ? cap : cap * room / width;
}

double x_tick_room(const Style& st) {
  // The labels' descenders reach about 0.35 cap below the capitals' baseline.
  return st.tick_major + st.tick_gap + 1.35 * st.tick_cap;
}

double widest_label(const AxisTicks& ticks, double cap, const Style& st) {
  double widest = 0.0;
  for (const auto& t : ticks.major) widest = std::max(widest, st.text_width(t.label, cap));
  return widest;
}

void draw_grid(PlotPage& page, const Mapping& m, const AxisTicks* x, const AxisTicks* y,
               const Style& st) {
  page.colour(grid_grey);
  page.line_width(st.grid_width);
  if (x != nullptr) {
    for (const auto& t : x->major)
      page.segment(m.px(t.position), m.box.y0, m.px(t.position), m.box.y1);
  }
  if (y != nullptr) {
    for (const auto& t : y->major)
      page.segment(m.box.x0, m.py(t.position), m.box.x1, m.py(t.position));
  }
}

void draw_frame(PlotPage& page, const Box& box, const Style& st) {
  page.colour(black);
  page.line_width(st.frame_width);
  page.polyline({box.x0, box.x1, box.x1, box.x0, box.x0}, {box.y0, box.y0, box.y1, box.y1, box.y0});
}

void draw_x_axis(PlotPage& page, const Mapping& m, const AxisTicks& ticks, const Style& st) {
  page.colour(black);
  page.line_width(st.frame_width);
  for (double p : ticks.minor) page.segment(m.px(p), m.box.y0, m.px(p), m.box.y0 - st.tick_minor);
  for (const auto& t : ticks.major) {
    page.segment(m.px(t.position), m.box.y0, m.px(t.position), m.box.y0 - st.tick_major);
  }
  page.colour(text_grey);
  const double y = m.box.y0 - st.tick_major - st.tick_gap - 0.5 * st.tick_cap;
  for (const auto& t : ticks.major) page.text(m.px(t.position), y, 0.0, 0.5, st.tick_cap, t.label);
}

void draw_y_axis(PlotPage& page, const Mapping& m, const AxisTicks& ticks, const Style& st,
                 bool right_side) {
  const double edge = right_side ? m.box.x1 : m.box.x0;
  const double out = right_side ? 1.0 : -1.0;
  page.colour(black);
  page.line_width(st.frame_width);
  for (double p : ticks.minor) page.segment(edge, m.py(p), edge + out * st.tick_minor, m.py(p));
  for (const auto& t : ticks.major) {
    page.segment(edge, m.py(t.position), edge + out * st.tick_major, m.py(t.position));
  }
  page.colour(text_grey);
  const double x = edge + out * (st.tick_major + st.tick_gap);
  for (const auto& t : ticks.major) {
    page.text(x, m.py(t.position), 0.0, right_side ? 0.0 : 1.0, st.tick_cap, t.label);
  }
}

AxisTicks ticks_for(const AxisRange& r, double length, const LabelExtent& extent, double gap) {
  return r.log ? log_ticks(r.lo, r.hi, length, extent, gap)
               : linear_ticks(r.lo, r.hi, length, extent, gap);
}

AxesLayout layout_axes(const Style& st, double width, double height, double top,
                       const std::string& x_label, const std::string& y_label,
                       double right_reserved, AxisRange x, AxisRange y) {
  const double x_title = x_label.empty() ? 0.0 : 1.9 * st.label_cap;
  const double y_title = y_label.empty() ? 0.0 : 1.9 * st.label_cap;
  const auto x_extent = [&](const std::string& s) { return st.text_width(s, st.tick_cap); };
  const auto y_extent = [&](const std::string&) { return st.tick_cap; };
  AxesLayout out;
  out.box.y1 = height - top - 0.6 * st.tick_cap;
  out.box.y0 = st.pad + x_title + (x_title > 0 ? 0.3 * st.label_gap : 0.0) + x_tick_room(st);
  out.box.x0 = 0.3 * width;
  out.box.x1 = width - std::max(right_reserved, st.pad);
  // The left margin depends on the y labels and the x ticks on the width left over: settle both.
  for (int pass = 0; pass < 3; ++pass) {
    out.y = ticks_for(y, out.box.height(), y_extent, 4.0 * st.tick_cap);
    const double y_labels = widest_label(out.y, st.tick_cap, st);
    out.box.x0 = st.pad + y_title + (y_title > 0 ? 0.3 * st.label_gap : 0.0) + y_labels +
                 st.tick_gap + st.tick_major;
    out.x = ticks_for(x, out.box.width(), x_extent, 2.0 * st.tick_cap);
    if (!out.x.major.empty()) {  // labels centred on the ends of the axis stick out by half
      const double first = x_extent(out.x.major.front().label);
      const double last = x_extent(out.x.major.back().label);
      const Mapping m{out.box, x.lo, x.hi, y.lo, y.hi};
      out.box.x0 = std::max(
          out.box.x0, st.pad + 0.5 * first - (m.px(out.x.major.front().position) - out.box.x0));
      const double overhang = 0.5 * last - (out.box.x1 - m.px(out.x.major.back().position));
      out.box.x1 = std::min(out.box.x1, width - st.pad - std::max(0.0, overhang));
    }
  }
  return out;
}

AxesLayout layout_axes(const Style& st, const Box& area, double top, const std::string& x_label,
                       const std::string& y_label, double right_reserved, AxisRange x,
                       AxisRange y) {
  auto out = layout_axes(st, area.width(), area.height(), top, x_label, y_label, right_reserved, x, y);
  out.box = Box{out.box.x0 + area.x0, out.box.y0 + area.y0, out.box.x1 + area.x0,
                out.box.y1 + area.y0};
  return out;
}

void draw_axis_titles(PlotPage& page, const Box& box, const std::string& x_label,
                      const std::string& y_label, const Style& st) {
  draw_axis_titles(page, box, x_label, y_label, st, whole_page(page));
}

void draw_axis_titles(PlotPage& page, const Box& box, const std::string& x_label,
                      const std::string& y_label, const Style& st, const Box& area) {
  page.colour(black);
  if (!x_label.empty()) {
    // Centred on the plot, so the room is twice the distance to the nearer side of the area.
    const double centre = 0.5 * (box.x0 + box.x1);
    const double room = 2.0 * std::min(centre - area.x0 - st.pad, area.x1 - st.pad - centre);
    page.text(centre, area.y0 + st.pad + 0.85 * st.label_cap, 0.0, 0.5,
              st.fit(x_label, st.label_cap, room), x_label);
  }
  if (!y_label.empty()) {
    page.text(area.x0 + st.pad + 0.75 * st.label_cap, 0.5 * (box.y0 + box.y1), 90.0, 0.5,
              st.fit(y_label, st.label_cap, box.height() + 0.5 * st.pad), y_label);
  }
}

double title_room(const std::string& title, const Style& st) {
  return title.empty() ? 0.0 : 2.0 * st.title_cap;
}

void draw_title(PlotPage& page, const std::string& title, const Style& st) {
  draw_title(page, title, st, whole_page(page));
}

void draw_title(PlotPage& page, const std::string& title, const Style& st, const Box& area) {
  if (title.empty()) return;
  page.colour(black);
  page.text(0.5 * (area.x0 + area.x1), area.y1 - st.pad - 0.7 * st.title_cap, 0.0, 0.5,
            st.fit(title, st.title_cap, area.width() - 2 * st.pad), title);
}

Box whole_page(const PlotPage& page) {
  return Box{0.0, 0.0, static_cast<double>(page.width()), static_cast<double>(page.height())};
}

namespace {

double swatch_width(const Style& st) { return 34 * st.scale; }

}  // namespace

void ellipse_polygon(double cx, double cy, double a, double b, double angle_rad, int n,
                     std::vector<double>& xs, std::vector<double>& ys) {
  const double c = std::cos(angle_rad), s = std::sin(angle_rad);
  for (int i = 0; i < n; ++i) {
    const double t = 2.0 * std::numbers::pi * i / n;
    const double u = a * std::cos(t), v = b * std::sin(t);
    xs.push_back(cx + u * c - v * s);
    ys.push_back(cy + u * s + v * c);
  }
}

void draw_ring(PlotPage& page, double x, double y, double radius, Rgb colour) {
  // White inside, so that a ring over a region or a line still reads as open.
  const double width = 0.35 * radius;
  page.colour({255, 255, 255});
  page.disc(x, y, radius);
  std::vector<double> xs, ys;
  ellipse_polygon(x, y, radius - 0.5 * width, radius - 0.5 * width, 0.0, 36, xs, ys);
  xs.push_back(xs.front()), ys.push_back(ys.front());
  page.colour(colour);
  page.line_width(width);
  page.polyline(xs, ys);
}

LegendLayout layout_legend(const std::vector<LegendEntry>& entries, double available_width,
                           const Style& st) {
  LegendLayout layout;
  if (entries.empty()) return layout;
  double widest = 0.0;
  for (const auto& e : entries) widest = std::max(widest, st.text_width(e.label, st.legend_cap));
  layout.column_width = swatch_width(st) + 0.6 * st.legend_cap + widest + 1.8 * st.legend_cap;
  const int n = static_cast<int>(entries.size());
  layout.columns = std::clamp(static_cast<int>(available_width / layout.column_width), 1, n);
  layout.rows = (n + layout.columns - 1) / layout.columns;
  // Balance the rows: as few columns as give the same number of rows.
  while (layout.columns > 1 && (n + layout.columns - 2) / (layout.columns - 1) == layout.rows) {
    --layout.columns;
  }
  layout.row_height = 1.9 * st.legend_cap;
  return layout;
}

void draw_legend(PlotPage& page, const std::vector<LegendEntry>& entries,
                 const LegendLayout& layout, double centre_x, double top_y, const Style& st) {
  if (entries.empty()) return;
  const double total = layout.columns * layout.column_width - 1.8 * st.legend_cap;
  const double left = centre_x - 0.5 * total;
  const double sw = swatch_width(st);
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const auto& e = entries[i];
    const int row = static_cast<int>(i) / layout.columns;
    const int column = static_cast<int>(i) % layout.columns;
    const double x = left + column * layout.column_width;
    const double y = top_y - (row + 0.5) * layout.row_height;
    const double half = 0.55 * st.legend_cap;
    if (e.kind == LegendEntry::Kind::band || e.with_band) {
      page.colour(e.colour, e.kind == LegendEntry::Kind::band ? 1.0 : band_alpha);
      page.rectangle(x, y - half, x + sw, y + half);
    }
    if (e.kind == LegendEntry::Kind::line) {
      page.colour(e.colour);
      page.line_width(st.curve_width);
      page.segment(x, y, x + sw, y);
    }
    if (e.kind == LegendEntry::Kind::marker) {
      page.colour(e.colour);
      page.line_width(st.curve_width * 0.8);
      page.segment(x + 0.5 * sw, y - half * 1.1, x + 0.5 * sw, y + half * 1.1);
    }
    if (e.kind == LegendEntry::Kind::marker || e.kind == LegendEntry::Kind::point ||
        e.with_marker) {
      page.colour(e.colour);
      page.disc(x + 0.5 * sw, y, 4.5 * st.scale);
    }
    if (e.kind == LegendEntry::Kind::open_point) {
      draw_ring(page, x + 0.5 * sw, y, 4.5 * st.scale, e.colour);
    }
    if (e.kind == LegendEntry::Kind::region) {
      std::vector<double> xs, ys;
      ellipse_polygon(x + 0.5 * sw, y, 0.5 * sw - 0.5 * e.outline.width_px, half, 0.0, 72, xs, ys);
      page.colour(e.colour, region_alpha);
      page.fill(xs, ys);
      xs.push_back(xs.front()), ys.push_back(ys.front());
      page.colour(e.colour);
      page.line_width(e.outline.width_px);
      page.dashes(e.outline.dashes_px);
      page.polyline(xs, ys);
      page.dashes({});
    }
    page.colour(text_grey);
    page.text(x + sw + 0.6 * st.legend_cap, y, 0.0, 0.0, st.legend_cap, e.label);
  }
}

std::string quoted_title(const std::string& title) {
  return title.empty() ? std::string("(untitled)") : "\"" + title + "\"";
}

void reject(const std::string& kind, const std::string& title, const std::string& what) {
  throw std::invalid_argument(kind + " " + quoted_title(title) + ": " + what);
}

void check_size(const ImageSize& size, const std::string& kind, const std::string& title) {
  if (size.width_px < 64 || size.height_px < 64 || size.width_px > 20000 ||
      size.height_px > 20000) {
    reject(kind, title,
           "image size " + std::to_string(size.width_px) + "x" + std::to_string(size.height_px) +
               " px is outside 64 to 20000 px a side");
  }
}

}  // namespace nibrig::ui::report::detail
