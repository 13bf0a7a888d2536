// write_print_sheet: a column of text beside a line plot and a scatter plot, on one page.
#include <algorithm>
#include <cmath>

#include "ui/report/chart_parts.hpp"
#include "ui/report/figures.hpp"
#include "ui/report/line_parts.hpp"
#include "ui/report/scatter_layout.hpp"

namespace nibrig::ui::report {

namespace {

using namespace detail;

constexpr const char* kPrintSheetKind = "print sheet";
// Share of the page's width the text column takes.
constexpr double kTextColumn = 0.38;

double row_height(bool heading, double cap) { return (heading ? 2.3 : 1.55) * cap; }

// A line broken at spaces into rows that fit `room` px at `cap`; a word longer than the room is a
// row of its own (drawn smaller to fit).
std::vector<std::string> wrapped(const std::string& text, double cap, double room, const Style& st) {
  std::vector<std::string> rows;
  std::string row;
  std::size_t at = 0;
  while (at <= text.size()) {
    const std::size_t space = std::min(text.find(' ', at), text.size());
    const std::string word = text.substr(at, space - at);
    const std::string longer = row.empty() ? word : row + " " + word;
    if (!row.empty() && st.text_width(longer, cap) > room) {
      rows.push_back(row);
      row = word;
    } else {
      row = longer;
    }
    at = space + 1;
  }
  rows.push_back(row);
  return rows;
}

struct Row {
  std::string text;
  bool heading, first_of_line;
};

void draw_text_column(PlotPage& page, const std::vector<SheetLine>& lines, const Box& area,
                      const Style& st) {
  const double heading_cap = st.label_cap, body_cap = st.tick_cap, indent = 0.8 * st.pad;
  const auto room = [&](bool heading) { return area.width() - 2 * st.pad - (heading ? 0.0 : indent); };
  std::vector<Row> rows;
  double needed = 0.0;
  for (const auto& line : lines) {
    const double cap = line.heading ? heading_cap : body_cap;
    bool first = true;
    for (auto& text : wrapped(line.text, cap, room(line.heading), st)) {
      rows.push_back({std::move(text), line.heading, first});
      // A heading's extra room is above its first row, so it sits close to the lines it heads.
      needed += first ? row_height(line.heading, cap) : row_height(false, cap);
      first = false;
    }
  }
  const double shrink = std::min(1.0, (area.height() - 2 * st.pad) / needed);
  double y = area.y1 - st.pad;
  for (const auto& row : rows) {
    const double cap = shrink * (row.heading ? heading_cap : body_cap);
    // Continued rows of a line are indented a little more than its first.
    const double x = area.x0 + st.pad + (row.heading ? 0.0 : indent) + (row.first_of_line ? 0.0 : 0.5 * indent);
    y -= row.first_of_line ? row_height(row.heading, cap) : row_height(false, cap);
    page.colour(row.heading ? black : text_grey);
    page.text(x, y + 0.75 * cap, 0.0, 0.0, st.fit(row.text, cap, area.x1 - x - st.pad), row.text);
  }
}

}  // namespace

void write_print_sheet(const PrintSheet& sheet, const std::filesystem::path& png) {
  check_size(sheet.size, kPrintSheetKind, sheet.title);
  const std::string name = std::string(kPrintSheetKind) + " " + quoted_title(sheet.title);
  if (sheet.line_plot) validate_line_series(*sheet.line_plot, (name + ": line plot").c_str());
  if (sheet.scatter_plot) validate_scatter(*sheet.scatter_plot, (name + ": scatter plot").c_str());

  const auto st = Style::for_size(sheet.size);
  const double width = sheet.size.width_px, height = sheet.size.height_px;
  const double below_title = height - st.pad - title_room(sheet.title, st);
  const bool figures = sheet.line_plot || sheet.scatter_plot;
  const double split = figures ? kTextColumn * width : width;
  const Box text{0.0, 0.0, split, below_title};
  const Box right{split, 0.0, width, below_title};
  // The line plot above the scatter when both: a spectrum reads well wide and low, a space needs
  // height for its equal axes.
  const double line_share = sheet.scatter_plot ? 0.40 : 1.0;
  const Box upper{right.x0, right.y1 - line_share * right.height(), right.x1, right.y1};
  const Box lower{right.x0, right.y0, right.x1, sheet.line_plot ? upper.y0 : right.y1};

  PlotPage page(sheet.title, png, sheet.size.width_px, sheet.size.height_px);
  draw_title(page, sheet.title, st);
  draw_text_column(page, sheet.lines, text, st);
  if (sheet.line_plot) draw_line_plot(page, *sheet.line_plot, upper, st);
  if (sheet.scatter_plot) {
    const auto f = layout_scatter(*sheet.scatter_plot, st, lower);
    draw_scatter(page, *sheet.scatter_plot, f, lower);
  }
  if (figures) {  // a thin rule between the text and the figures
    page.colour(grid_grey);
    page.line_width(st.grid_width);
    page.segment(split, st.pad, split, below_title - st.pad);
  }
  page.commit();
}

}  // namespace nibrig::ui::report
