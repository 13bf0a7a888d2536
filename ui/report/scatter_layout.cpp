#include "ui/report/scatter_layout.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace nibrig::ui::report::detail {

namespace {

// Points without a group, when other points have one: neutral, so they do not read as a group.
constexpr Rgb ungrouped_grey{110, 110, 110};
// Region samples in the legend stand for every group's regions: drawn in a neutral dark grey.
constexpr Rgb legend_region_grey{90, 90, 90};

// Something that must fit inside the plot box: a data position with room around it in pixels.
struct Keep {
  double x, y;
  double left, right, below, above;  // px
};

struct Ranges {
  double x_lo, x_hi, y_lo, y_hi;
};

// Widens the narrower range (in data units per pixel of the box), centred, so that both axes have
// the same scale.
Ranges equalised(Ranges r, const Box& box) {
  const double ux = (r.x_hi - r.x_lo) / box.width(), uy = (r.y_hi - r.y_lo) / box.height();
  if (ux < uy) {
    const double half = 0.5 * uy * box.width(), centre = 0.5 * (r.x_lo + r.x_hi);
    r.x_lo = centre - half, r.x_hi = centre + half;
  } else {
    const double half = 0.5 * ux * box.height(), centre = 0.5 * (r.y_lo + r.y_hi);
    r.y_lo = centre - half, r.y_hi = centre + half;
  }
  return r;
}

// Narrows the box, centred, to the exact common scale: the ticks were chosen for a box a pixel or
// two larger, which they do not notice.
Box narrowed(Box box, const Ranges& r) {
  const double ux = (r.x_hi - r.x_lo) / box.width(), uy = (r.y_hi - r.y_lo) / box.height();
  if (ux < uy) {
    const double width = (r.x_hi - r.x_lo) / uy, centre = 0.5 * (box.x0 + box.x1);
    box.x0 = centre - 0.5 * width, box.x1 = centre + 0.5 * width;
  } else {
    const double height = (r.y_hi - r.y_lo) / ux, centre = 0.5 * (box.y0 + box.y1);
    box.y0 = centre - 0.5 * height, box.y1 = centre + 0.5 * height;
  }
  return box;
}

// A range with some extent: a single value gets room around it.
void open_up(double& lo, double& hi) {
  if (hi - lo > 0.0) return;
  const double half = std::max(std::abs(lo) * 0.1, 0.5);
  lo -= half, hi += half;
}

}  // namespace

LineStyle region_outline(std::size_t k, const Style& st) {
  const double s = st.scale;
  switch (k % 4) {
    case 0:
      return {1.9 * s, {}};
    case 1:
      return {1.4 * s, {7.0 * s, 4.0 * s}};
    case 2:
      return {1.4 * s, {1.8 * s, 3.2 * s}};
    default:
      return {1.4 * s, {8.0 * s, 3.5 * s, 1.8 * s, 3.5 * s}};
  }
}

std::pair<double, double> ellipse_half_extents(const Ellipse& e) {
  const double c = std::cos(e.angle_rad), s = std::sin(e.angle_rad);
  const double a = e.semi_axis_1, b = e.semi_axis_2;
  return {std::sqrt(a * a * c * c + b * b * s * s), std::sqrt(a * a * s * s + b * b * c * c)};
}

ScatterFrame layout_scatter(const ScatterPlot& plot) {
  return layout_scatter(plot, Style::for_size(plot.size),
                        Box{0.0, 0.0, static_cast<double>(plot.size.width_px),
                            static_cast<double>(plot.size.height_px)});
}

ScatterFrame layout_scatter(const ScatterPlot& plot, const Style& style, const Box& area) {
  ScatterFrame f;
  f.style = style;
  const auto& st = f.style;

  // Colours and legend: groups in order of first appearance.
  std::vector<std::string> groups;
  bool any_hollow = false;
  std::size_t styles = 0;
  for (const auto& p : plot.points) {
    if (!p.group.empty() && std::find(groups.begin(), groups.end(), p.group) == groups.end())
      groups.push_back(p.group);
    any_hollow = any_hollow || p.hollow;
    styles = std::max(styles, p.regions.size());
  }
  const auto& palette = categorical_palette();
  for (const auto& p : plot.points) {
    const auto it = std::find(groups.begin(), groups.end(), p.group);
    f.colours.push_back(
        it == groups.end()
            ? (groups.empty() ? palette[0] : ungrouped_grey)
            : palette[static_cast<std::size_t>(it - groups.begin()) % palette.size()]);
  }
  for (std::size_t g = 0; g < groups.size(); ++g)
    f.legend.push_back({groups[g], palette[g % palette.size()], LegendEntry::Kind::point});
  for (std::size_t k = 0; k < styles; ++k) {
    f.region_outlines.push_back(region_outline(k, st));
    if (k < plot.region_labels.size()) {
      LegendEntry e{plot.region_labels[k], legend_region_grey, LegendEntry::Kind::region};
      e.outline = f.region_outlines.back();
      f.legend.push_back(e);
    }
  }
  if (any_hollow)
    f.legend.push_back({"placed from descriptors", ungrouped_grey, LegendEntry::Kind::open_point});
  f.legend_layout = layout_legend(f.legend, area.width() - 2 * st.pad, st);
  f.legend_top = area.y1 - st.pad - title_room(plot.title, st);
  const double top = st.pad + title_room(plot.title, st) +
                     (f.legend.empty() ? 0.0 : f.legend_layout.height() + 0.5 * st.label_gap);

  // Marks and labels, in pixels.
  f.marker_radius = 4.5 * st.scale;
  f.label_cap = 0.78 * st.tick_cap;
  const double label_height = 1.4 * f.label_cap;
  f.placement.marker_radius = f.marker_radius;
  f.placement.gap = 0.35 * f.label_cap;
  f.placement.skip_overlapping = plot.points.size() > max_points_all_labelled || plot.leave_out_crowded_labels;
  // Labels keep clear of the frame by this much.
  const double inset = 0.25 * st.pad;

  // What must fit: markers with a little air, region bounding boxes with their outline, and each
  // label beside its point, at its height and on one side or the other.
  std::vector<Keep> keep;
  const double air = f.marker_radius + 0.5 * st.pad;
  double x_lo = std::numeric_limits<double>::infinity(), x_hi = -x_lo, y_lo = x_lo, y_hi = -x_lo;
  for (const auto& p : plot.points) {
    const double v = p.label.empty() ? air : std::max(air, 0.5 * label_height + inset);
    keep.push_back({p.x, p.y, air, air, v, v});
    x_lo = std::min(x_lo, p.x), x_hi = std::max(x_hi, p.x);
    y_lo = std::min(y_lo, p.y), y_hi = std::max(y_hi, p.y);
    for (std::size_t k = 0; k < p.regions.size(); ++k) {
      const auto& e = p.regions[k];
      const auto [hx, hy] = ellipse_half_extents(e);
      const double line = f.region_outlines[k].width_px;
      keep.push_back({e.centre_x - hx, e.centre_y - hy, line, 0.0, line, 0.0});
      keep.push_back({e.centre_x + hx, e.centre_y + hy, 0.0, line, 0.0, line});
      x_lo = std::min(x_lo, e.centre_x - hx), x_hi = std::max(x_hi, e.centre_x + hx);
      y_lo = std::min(y_lo, e.centre_y - hy), y_hi = std::max(y_hi, e.centre_y + hy);
    }
  }
  open_up(x_lo, x_hi);
  open_up(y_lo, y_hi);

  // Pixel room is turned into data room at the current scale, which the added room shrinks a
  // little: repeat until everything fits (a few passes; each finds less missing).
  double pad_left = 0, pad_right = 0, pad_below = 0, pad_above = 0;
  for (int pass = 0; pass < 12; ++pass) {
    Ranges r{x_lo - pad_left, x_hi + pad_right, y_lo - pad_below, y_hi + pad_above};
    auto axes = layout_axes(st, area, top, plot.x_label, plot.y_label, st.pad,
                            {r.x_lo, r.x_hi}, {r.y_lo, r.y_hi});
    if (plot.equal_axes) {
      r = equalised(r, axes.box);
      axes = layout_axes(st, area, top, plot.x_label, plot.y_label, st.pad,
                         {r.x_lo, r.x_hi}, {r.y_lo, r.y_hi});
      axes.box = narrowed(axes.box, r);
    }
    f.axes = axes;
    f.mapping = {axes.box, r.x_lo, r.x_hi, r.y_lo, r.y_hi};
    const auto& m = f.mapping;
    const auto& box = axes.box;

    double left = 0, right = 0, below = 0, above = 0;  // px missing on each side
    for (const auto& k : keep) {
      left = std::max(left, box.x0 - (m.px(k.x) - k.left));
      right = std::max(right, m.px(k.x) + k.right - box.x1);
      below = std::max(below, box.y0 - (m.py(k.y) - k.below));
      above = std::max(above, m.py(k.y) + k.above - box.y1);
    }
    for (const auto& p : plot.points) {
      if (p.label.empty()) continue;
      const double reach =
          f.marker_radius + f.placement.gap + st.text_width(p.label, f.label_cap) + inset;
      const double short_right = m.px(p.x) + reach - box.x1;
      const double short_left = box.x0 - (m.px(p.x) - reach);
      if (short_right <= 0.0 || short_left <= 0.0) continue;
      if (short_right <= short_left) {
        right = std::max(right, short_right);
      } else {
        left = std::max(left, short_left);
      }
    }
    if (std::max({left, right, below, above}) < 0.5) break;
    // 2 % more than missing, so that the passes do not creep up on the edge.
    const double ux = (r.x_hi - r.x_lo) / box.width() * 1.02;
    const double uy = (r.y_hi - r.y_lo) / box.height() * 1.02;
    pad_left += left * ux, pad_right += right * ux;
    pad_below += below * uy, pad_above += above * uy;
  }

  const auto& m = f.mapping;
  for (const auto& p : plot.points) {
    f.label_requests.push_back({m.px(p.x), m.py(p.y),
                                p.label.empty() ? 0.0 : st.text_width(p.label, f.label_cap),
                                label_height, p.hollow});
  }
  const auto& b = f.axes.box;
  f.placement.bounds = {b.x0 + inset, b.y0 + inset, b.x1 - inset, b.y1 - inset};
  f.labels = place_labels(f.label_requests, f.placement);
  return f;
}

}  // namespace nibrig::ui::report::detail
