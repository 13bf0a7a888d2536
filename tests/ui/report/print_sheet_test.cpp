// The print sheet (write_print_sheet): the text column on the left, the line plot above the
// scatter plot on the right, each figure inside its own part of the page, nothing at the border
// however much text there is, and bad input refused naming the sheet and the figure.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tests/support/test_paths.hpp"
#include "tests/ui/report/figure_checks.hpp"
#include "tests/ui/report/png_reader.hpp"
#include "ui/report/colour_maps.hpp"
#include "ui/report/figures.hpp"

namespace nibrig::ui::report {
namespace {

namespace fs = std::filesystem;

// One flat curve at 1e-3 across the plot: a row of the first colour.
LinePlot flat_spectrum() {
  LinePlot plot;
  plot.title = "Predicted vibration on protector";
  plot.x_label = "frequency (Hz)";
  plot.y_label = "amplitude (m/s#u2#d)";
  plot.log_y = true;
  LineSeries s;
  s.label = "50 mm/s";
  for (int i = 0; i < 200; ++i) s.x.push_back(5.0 * i), s.y.push_back(1e-3 * (i == 100 ? 2.0 : 1.0));
  plot.series.push_back(s);
  return plot;
}

// Three tools in a ring, each of its own group: markers in the first three colours.
ScatterPlot small_space() {
  ScatterPlot plot;
  plot.title = "Where it lies in the perceptual space";
  plot.x_label = "axis 1";
  plot.y_label = "axis 2";
  for (int i = 0; i < 3; ++i) {
    const double t = 2.0 * std::numbers::pi * i / 3.0;
    plot.points.push_back({"tool " + std::to_string(i), std::cos(t), std::sin(t), "group " + std::to_string(i), {}, false});
  }
  return plot;
}

PrintSheet sample_sheet() {
  PrintSheet sheet;
  sheet.title = "nibrig stylus DM85:0.62,vero:0.38,tip=2.7mm";
  sheet.lines = {{"Design", true}, {"stylus_vero_tip2mm, meshed at 0.60 mm", false}, {"Files", true}, {"stylus.3mf", false}};
  sheet.line_plot = flat_spectrum();
  sheet.scatter_plot = small_space();
  return sheet;
}

struct Found {
  int count = 0;
  int x_min = 1 << 30, x_max = -1, y_min = 1 << 30, y_max = -1;  // image pixels, y from the top
};

Found find_colour(const nibrig::test::RgbImage& img, Rgb colour, int tolerance = 10) {
  Found f;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      if (nibrig::test::near(img.at(x, y), colour, tolerance)) {
        ++f.count;
        f.x_min = std::min(f.x_min, x), f.x_max = std::max(f.x_max, x);
        f.y_min = std::min(f.y_min, y), f.y_max = std::max(f.y_max, y);
      }
  return f;
}

// Dark pixels (text) in columns [x0, x1).
int dark_pixels(const nibrig::test::RgbImage& img, int x0, int x1) {
  int n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = x0; x < x1; ++x) n += nibrig::test::near(img.at(x, y), {40, 40, 40}, 45);
  return n;
}

TEST(ReportPrintSheet, TextOnTheLeftTheLinePlotAboveTheScatterOnTheRight) {
  const auto dir = nibrig::test::scratch_dir("print_sheet");
  const auto sheet = sample_sheet();
  write_print_sheet(sheet, dir / "sheet.png");
  EXPECT_EQ(nibrig::test::png_header(dir / "sheet.png").width, 2000u);
  EXPECT_EQ(nibrig::test::png_header(dir / "sheet.png").height, 1500u);
  test::expect_white_border(dir / "sheet.png");

  const auto img = nibrig::test::decode_png(dir / "sheet.png");
  const auto& palette = categorical_palette();
  // The text column is the left 38 % (print_sheet.cpp): the figures' colours stay right of it.
  const int split = static_cast<int>(0.38 * img.width);
  const Found curve = find_colour(img, palette[0]);
  const Found second = find_colour(img, palette[1]), third = find_colour(img, palette[2]);
  ASSERT_GT(curve.count, 0);
  ASSERT_GT(second.count, 0);
  ASSERT_GT(third.count, 0);
  for (const Found* f : {&curve, &second, &third}) EXPECT_GT(f->x_min, split);
  // The markers of groups 1 and 2 are the scatter's alone: below the line plot, which takes the
  // upper 40 % of the part under the title.
  EXPECT_GT(second.y_min, img.height * 0.40);
  EXPECT_GT(third.y_min, img.height * 0.40);
  // The flat curve (and its legend swatch) lies in the upper part; the first group's marker below.
  EXPECT_LT(curve.y_min, img.height * 0.45);
  EXPECT_GT(curve.y_max, img.height * 0.45);
  // The text is drawn in its column.
  EXPECT_GT(dark_pixels(img, 0, split), 500);
}

TEST(ReportPrintSheet, WithoutFiguresTheTextHasThePageAndNoFigureIsDrawn) {
  const auto dir = nibrig::test::scratch_dir("print_sheet_text");
  auto sheet = sample_sheet();
  sheet.line_plot.reset();
  sheet.scatter_plot.reset();
  write_print_sheet(sheet, dir / "sheet.png");
  test::expect_white_border(dir / "sheet.png");
  const auto img = nibrig::test::decode_png(dir / "sheet.png");
  for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(find_colour(img, categorical_palette()[k]).count, 0) << k;
  EXPECT_GT(dark_pixels(img, 0, img.width), 500);
}

TEST(ReportPrintSheet, LongAndManyLinesShrinkToStayOnThePage) {
  const auto dir = nibrig::test::scratch_dir("print_sheet_long");
  auto sheet = sample_sheet();
  sheet.lines.push_back({std::string(300, 'W'), false});
  for (int i = 0; i < 150; ++i) sheet.lines.push_back({"region " + std::to_string(i) + ": VeroClear, 123.4 mm3", i % 10 == 0});
  write_print_sheet(sheet, dir / "sheet.png");
  test::expect_white_border(dir / "sheet.png");
  // Nothing of the text crosses into the figures: the 300 W's end before the split.
  const auto img = nibrig::test::decode_png(dir / "sheet.png");
  const int split = static_cast<int>(0.38 * img.width);
  int beyond = 0;
  for (int y = img.height / 10; y < img.height; ++y)  // below the title, which spans the page
    beyond += nibrig::test::near(img.at(split - 2, y), {40, 40, 40}, 45);
  EXPECT_EQ(beyond, 0);
}

TEST(ReportPrintSheet, BadInputIsRefusedNamingTheSheetAndTheFigure) {
  auto sheet = sample_sheet();
  sheet.line_plot->series[0].y[3] = -1.0;
  test::expect_rejected([&](const fs::path& p) { write_print_sheet(sheet, p); }, sheet.title,
                        "line plot");
  sheet = sample_sheet();
  sheet.scatter_plot->points.clear();
  test::expect_rejected([&](const fs::path& p) { write_print_sheet(sheet, p); }, sheet.title,
                        "scatter plot");
  sheet = sample_sheet();
  sheet.size = {10, 10};
  test::expect_rejected([&](const fs::path& p) { write_print_sheet(sheet, p); }, sheet.title, "10");
}

}  // namespace
}  // namespace nibrig::ui::report
