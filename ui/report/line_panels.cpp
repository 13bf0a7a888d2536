// write_line_panels: line plots side by side (small multiples) under one title and one legend.
#include <algorithm>
#include <stdexcept>

#include "ui/report/chart_parts.hpp"
#include "ui/report/figures.hpp"
#include "ui/report/line_parts.hpp"

namespace nibrig::ui::report {

namespace {

using namespace detail;

constexpr const char* kLinePanelsKind = "line panels";

void validate(const LinePanels& figure) {
  check_size(figure.size, kLinePanelsKind, figure.title);
  if (figure.panels.empty()) reject(kLinePanelsKind, figure.title, "no panels to draw");
  if (figure.columns < 1)
    reject(kLinePanelsKind, figure.title, "columns is " + std::to_string(figure.columns) + ", not >= 1");
  for (std::size_t k = 0; k < figure.panels.size(); ++k) {
    const auto& panel = figure.panels[k];
    try {
      validate_line_series(panel, ("panel " + std::to_string(k)).c_str());
    } catch (const std::invalid_argument& e) {
      reject(kLinePanelsKind, figure.title, e.what());
    }
    if (figure.shared_axes && panel.log_y != figure.panels.front().log_y)
      reject(kLinePanelsKind, figure.title,
             "panel " + std::to_string(k) + " " + quoted_title(panel.title) +
                 " has another log_y than panel 0 on shared axes");
  }
}

}  // namespace

void write_line_panels(const LinePanels& figure, const std::filesystem::path& png) {
  validate(figure);
  const auto st = Style::for_size(figure.size);
  const double width = figure.size.width_px, height = figure.size.height_px;
  const std::size_t n = figure.panels.size();
  const std::size_t columns = std::min(n, static_cast<std::size_t>(figure.columns));
  const std::size_t rows = (n + columns - 1) / columns;

  LineExtent shared;
  for (const auto& panel : figure.panels) shared.add(panel);
  const auto legend = line_legend(figure.panels.front());
  const auto legend_layout = layout_legend(legend, width - 2 * st.pad, st);
  const double top = st.pad + title_room(figure.title, st) +
                     (legend.empty() ? 0.0 : legend_layout.height() + 0.5 * st.label_gap);
  const double cell_width = width / static_cast<double>(columns);
  const double cell_height = (height - top) / static_cast<double>(rows);

  detail::PlotPage page(figure.title, png, figure.size.width_px, figure.size.height_px);
  for (std::size_t k = 0; k < n; ++k) {
    const auto& panel = figure.panels[k];
    const std::size_t row = k / columns, column = k % columns;
    const Box cell{static_cast<double>(column) * cell_width,
                   height - top - static_cast<double>(row + 1) * cell_height,
                   static_cast<double>(column + 1) * cell_width,
                   height - top - static_cast<double>(row) * cell_height};
    LineExtent own;
    own.add(panel);
    const LineExtent& extent = figure.shared_axes ? shared : own;
    const AxisRange xr = extent.x_range(), yr = extent.y_range(panel.log_y);
    // Axis titles once: y at the start of each row, x under the last panel of each column.
    const std::string y_label = column == 0 ? panel.y_label : std::string();
    const std::string x_label = k + columns >= n ? panel.x_label : std::string();
    const double panel_title_room = panel.title.empty() ? 0.0 : 1.8 * st.label_cap;
    const auto axes = layout_axes(st, cell, panel_title_room, x_label, y_label, st.pad, xr, yr);
    const Mapping m{axes.box, xr.lo, xr.hi, yr.lo, yr.hi};

    draw_grid(page, m, &axes.x, &axes.y, st);
    draw_curves(page, panel, m, st);
    draw_frame(page, axes.box, st);
    draw_x_axis(page, m, axes.x, st);
    draw_y_axis(page, m, axes.y, st);
    draw_axis_titles(page, axes.box, x_label, y_label, st, cell);
    if (!panel.title.empty()) {
      page.colour(black);
      page.text(0.5 * (axes.box.x0 + axes.box.x1), cell.y1 - 0.8 * st.label_cap, 0.0, 0.5,
                st.fit(panel.title, st.label_cap, cell.width() - 2 * st.pad), panel.title);
    }
  }
  draw_title(page, figure.title, st);
  draw_legend(page, legend, legend_layout, 0.5 * width,
              height - st.pad - title_room(figure.title, st), st);
  page.commit();
}

}  // namespace nibrig::ui::report
