// write_line_plot: curves with optional shaded bands, a legend above the plot.
#include "ui/report/chart_parts.hpp"
#include "ui/report/figures.hpp"
#include "ui/report/line_parts.hpp"

namespace nibrig::ui::report {

namespace detail {

void draw_line_plot(PlotPage& page, const LinePlot& plot, const Box& area, const Style& st) {
  LineExtent extent;
  extent.add(plot);
  const auto legend = line_legend(plot);
  const auto legend_layout = layout_legend(legend, area.width() - 2 * st.pad, st);
  const double top = st.pad + title_room(plot.title, st) +
                     (legend.empty() ? 0.0 : legend_layout.height() + 0.5 * st.label_gap);
  const AxisRange xr = extent.x_range(), yr = extent.y_range(plot.log_y);
  const auto axes = layout_axes(st, area, top, plot.x_label, plot.y_label, st.pad, xr, yr);
  const Mapping m{axes.box, xr.lo, xr.hi, yr.lo, yr.hi};

  draw_grid(page, m, &axes.x, &axes.y, st);
  draw_curves(page, plot, m, st);
  draw_frame(page, axes.box, st);
  draw_x_axis(page, m, axes.x, st);
  draw_y_axis(page, m, axes.y, st);
  draw_axis_titles(page, axes.box, plot.x_label, plot.y_label, st, area);
  draw_title(page, plot.title, st, area);
  draw_legend(page, legend, legend_layout, 0.5 * (axes.box.x0 + axes.box.x1),
              area.y1 - st.pad - title_room(plot.title, st), st);
}

}  // namespace detail

namespace {

using namespace detail;

constexpr const char* kLinePlotKind = "line plot";

}  // namespace

void write_line_plot(const LinePlot& plot, const std::filesystem::path& png) {
  check_size(plot.size, kLinePlotKind, plot.title);
  validate_line_series(plot, kLinePlotKind);
  detail::PlotPage page(plot.title, png, plot.size.width_px, plot.size.height_px);
  draw_line_plot(page, plot, whole_page(page), Style::for_size(plot.size));
  page.commit();
}

}  // namespace nibrig::ui::report
