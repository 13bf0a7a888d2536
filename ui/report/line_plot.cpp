// write_line_plot: curves with optional shaded bands, a legend above the plot.
#include "ui/report/chart_parts.hpp"
#include "ui/report/figures.hpp"
#include "ui/report/line_parts.hpp"

namespace nibrig::ui::report {

namespace {

using namespace detail;

constexpr const char* kLinePlotKind = "line plot";

}  // namespace

void write_line_plot(const LinePlot& plot, const std::filesystem::path& png) {
  check_size(plot.size, kLinePlotKind, plot.title);
  validate_line_series(plot, kLinePlotKind);
  const auto st = Style::for_size(plot.size);
  const double width = plot.size.width_px, height = plot.size.height_px;

  LineExtent extent;
  extent.add(plot);
  const auto legend = line_legend(plot);
  const auto legend_layout = layout_legend(legend, width - 2 * st.pad, st);
  const double top = st.pad + title_room(plot.title, st) +
                     (legend.empty() ? 0.0 : legend_layout.height() + 0.5 * st.label_gap);
  const auto axes = layout_axes(st, width, height, top, plot.x_label, plot.y_label, st.pad,
                                extent.x_range(), extent.y_range(plot.log_y));
  const Mapping m{axes.box, extent.x_range().lo, extent.x_range().hi, extent.y_range(plot.log_y).lo,
                  extent.y_range(plot.log_y).hi};

  detail::PlotPage page(plot.title, png, plot.size.width_px, plot.size.height_px);
  draw_grid(page, m, &axes.x, &axes.y, st);
  draw_curves(page, plot, m, st);
  draw_frame(page, axes.box, st);
  draw_x_axis(page, m, axes.x, st);
  draw_y_axis(page, m, axes.y, st);
  draw_axis_titles(page, axes.box, plot.x_label, plot.y_label, st);
  draw_title(page, plot.title, st);
  draw_legend(page, legend, legend_layout, 0.5 * (axes.box.x0 + axes.box.x1),
              height - st.pad - title_room(plot.title, st), st);
  page.commit();
}

}  // namespace nibrig::ui::report
