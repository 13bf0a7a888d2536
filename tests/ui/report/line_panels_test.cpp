// Small multiples (write_line_panels): each panel inside its own part of the image, shared axes
// that really are shared, nothing at the border, and bad input refused naming the panel.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "tests/support/test_paths.hpp"
#include "tests/ui/report/figure_checks.hpp"
#include "tests/ui/report/png_reader.hpp"
#include "ui/report/colour_maps.hpp"
#include "ui/report/figures.hpp"

namespace nibrig::ui::report {
namespace {

namespace fs = std::filesystem;

// A panel with two flat curves: the first at `level`, the second ten times higher.
LinePlot flat_panel(const std::string& title, double level) {
  LinePlot panel;
  panel.title = title;
  panel.x_label = "frequency (Hz)";
  panel.y_label = "amplitude (m/s#u2#d)";
  panel.log_y = true;
  for (double scale : {1.0, 10.0}) {
    LineSeries s;
    s.label = scale == 1.0 ? "measured" : "predicted";
    for (int i = 0; i < 100; ++i) s.x.push_back(5.0 * i), s.y.push_back(scale * level);
    panel.series.push_back(s);
  }
  return panel;
}

// Image rows (from the top) where the first series' colour appears within columns [x0, x1).
std::vector<int> rows_of_first_colour(const nibrig::test::RgbImage& img, int x0, int x1) {
  std::vector<int> rows;
  const Rgb first = categorical_palette()[0];
  for (int y = 0; y < img.height; ++y) {
    int hits = 0;
    for (int x = x0; x < x1; ++x) hits += nibrig::test::near(img.at(x, y), first, 12);
    if (hits > (x1 - x0) / 3) rows.push_back(y);  // a horizontal line across most of the panel
  }
  return rows;
}

// The grey of a plot's only muted series (line_parts.cpp).
Rgb series_grey_for_test() { return Rgb{140, 140, 140}; }

double mean(const std::vector<int>& v) {
  double sum = 0;
  for (int x : v) sum += x;
  return v.empty() ? std::nan("") : sum / static_cast<double>(v.size());
}

TEST(ReportLinePanels, EachPanelDrawsInItsOwnColumnAndSharedAxesAreShared) {
  const auto dir = nibrig::test::scratch_dir("report_panels");
  LinePanels figure;
  figure.title = "Predicted and measured, by speed";
  figure.panels = {flat_panel("17 mm/s", 1e-3), flat_panel("110 mm/s", 1e-2),
                   flat_panel("250 mm/s", 1e-1)};
  write_line_panels(figure, dir / "shared.png");
  figure.shared_axes = false;
  write_line_panels(figure, dir / "own.png");
  for (const char* name : {"shared.png", "own.png"}) {
    EXPECT_EQ(nibrig::test::png_header(dir / name).width, 1800u);
    EXPECT_EQ(nibrig::test::png_header(dir / name).height, 700u);
    test::expect_white_border(dir / name);
  }

  const auto shared = nibrig::test::decode_png(dir / "shared.png");
  const auto own = nibrig::test::decode_png(dir / "own.png");
  const int third = shared.width / 3;
  std::vector<double> shared_rows, own_rows;
  for (int k = 0; k < 3; ++k) {
    // Every panel has its own horizontal line of the first colour, inside its own third.
    const auto s = rows_of_first_colour(shared, k * third, (k + 1) * third);
    const auto o = rows_of_first_colour(own, k * third, (k + 1) * third);
    ASSERT_FALSE(s.empty()) << "panel " << k << " (shared axes) drew no curve in its column";
    ASSERT_FALSE(o.empty()) << "panel " << k << " (own axes) drew no curve in its column";
    shared_rows.push_back(mean(s));
    own_rows.push_back(mean(o));
  }
  // Shared: a level ten times higher sits clearly higher (a smaller row) in the next panel.
  EXPECT_GT(shared_rows[0] - shared_rows[1], 40.0);
  EXPECT_GT(shared_rows[1] - shared_rows[2], 40.0);
  // Own axes: each panel spans its own decade, so the lines sit at the same height in each.
  EXPECT_NEAR(own_rows[0], own_rows[1], 3.0);
  EXPECT_NEAR(own_rows[1], own_rows[2], 3.0);
}

TEST(ReportLinePanels, MorePanelsThanColumnsWrapIntoRows) {
  const auto dir = nibrig::test::scratch_dir("report_panels_rows");
  LinePanels figure;
  figure.columns = 2;
  figure.size = {1200, 1000};
  for (int k = 0; k < 3; ++k) figure.panels.push_back(flat_panel("panel", 1e-2));
  write_line_panels(figure, dir / "rows.png");
  test::expect_white_border(dir / "rows.png");
  const auto img = nibrig::test::decode_png(dir / "rows.png");
  const auto left = rows_of_first_colour(img, 0, img.width / 2);
  const auto right = rows_of_first_colour(img, img.width / 2, img.width);
  // Two lines on the left (rows 1 and 2), one on the right (row 1 only).
  ASSERT_FALSE(left.empty());
  ASSERT_FALSE(right.empty());
  EXPECT_GT(left.back() - left.front(), img.height / 3);
  EXPECT_LT(right.back() - right.front(), img.height / 10);
  EXPECT_LT(right.back(), img.height / 2);
}

TEST(ReportLinePanels, MutedReferencesAreGreyAndLieUnderTheCurves) {
  const auto dir = nibrig::test::scratch_dir("report_muted");
  LinePlot plot = flat_panel("", 1e-2);   // measured, then predicted ten times higher
  LineSeries reference = plot.series[1];  // a muted reference exactly under the predicted curve
  reference.label = "baseline";
  reference.muted = true;
  plot.series.insert(plot.series.begin(), reference);
  plot.title = "Muted";
  write_line_plot(plot, dir / "muted.png");
  const auto img = nibrig::test::decode_png(dir / "muted.png");
  // The coloured curves keep the first two colours although the muted series comes first: each
  // draws a line across the plot. The grey line lies exactly under the predicted one, drawn before
  // it and thinner, so none of it shows on the rows of that line.
  const auto line_rows = [&](Rgb colour, int tolerance) {
    std::vector<int> rows;
    for (int y = 0; y < img.height; ++y) {
      int hits = 0;
      for (int x = 0; x < img.width; ++x) hits += nibrig::test::near(img.at(x, y), colour, tolerance);
      if (hits > img.width / 2) rows.push_back(y);
    }
    return rows;
  };
  const auto measured_rows = line_rows(categorical_palette()[0], 12);
  const auto predicted_rows = line_rows(categorical_palette()[1], 12);
  ASSERT_FALSE(measured_rows.empty());
  ASSERT_FALSE(predicted_rows.empty());
  const Rgb grey = series_grey_for_test();
  int hidden_grey = 0;
  for (int y = predicted_rows.front() - 3; y <= predicted_rows.back() + 3; ++y)
    for (int x = img.width / 4; x < 3 * img.width / 4; ++x)
      hidden_grey += nibrig::test::near(img.at(x, y), grey, 6);
  EXPECT_EQ(hidden_grey, 0);
  // The baseline's legend swatch is that grey.
  int legend_grey = 0;
  for (int y = 0; y < predicted_rows.front() - 10; ++y)
    for (int x = 0; x < img.width; ++x) legend_grey += nibrig::test::near(img.at(x, y), grey, 6);
  EXPECT_GT(legend_grey, 20);
}

TEST(ReportLinePanels, BadFiguresAreRefusedNamingThePanel) {
  const auto refuse = [](const std::function<void(LinePanels&)>& spoil, const std::string& fault) {
    LinePanels figure;
    figure.title = "By speed";
    figure.panels = {flat_panel("a", 1e-2), flat_panel("b", 1e-2)};
    spoil(figure);
    test::expect_rejected([&](const fs::path& p) { write_line_panels(figure, p); }, figure.title,
                          fault);
  };
  refuse([](LinePanels& f) { f.panels.clear(); }, "no panels");
  refuse([](LinePanels& f) { f.columns = 0; }, "columns is 0");
  refuse([](LinePanels& f) { f.panels[1].series[0].y[3] = -1.0; },
         "panel 1 \"b\": series 0 (measured) y[3] = -1.000000 cannot be shown on a log axis");
  refuse([](LinePanels& f) { f.panels[1].log_y = false; }, "another log_y than panel 0");
}

}  // namespace
}  // namespace nibrig::ui::report
