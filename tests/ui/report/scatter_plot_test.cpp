// The scatter plot as a file and as a layout: markers in their group colour where the axes put
// them, ellipse outlines at their semi-axes on equal axes, axes that hold each region's exact
// bounding box, a legend with what is used, a hundred labelled points, and bad input refused.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <thread>

#include "tests/support/test_paths.hpp"
#include "tests/ui/report/figure_checks.hpp"
#include "tests/ui/report/png_reader.hpp"
#include "ui/report/colour_maps.hpp"
#include "ui/report/figures.hpp"
#include "ui/report/scatter_layout.hpp"

namespace nibrig::ui::report {
namespace {

namespace fs = std::filesystem;
using detail::layout_scatter;

const Rgb white{255, 255, 255};

// A small perceptual space: three groups of tools, each with a 68 % and a 95 % region (the 95 %
// ellipse of a 2-D normal is sqrt(5.991 / 2.279) = 1.62 times the 68 % one).
ScatterPlot sample_space(std::size_t n = 9) {
  ScatterPlot plot;
  plot.title = "Perceptual space";
  plot.x_label = "dimension 1";
  plot.y_label = "dimension 2";
  plot.region_labels = {"68 %", "95 %"};
  const char* groups[] = {"pencils", "printed nibs", "commercial styli"};
  for (std::size_t i = 0; i < n; ++i) {
    const double t = 2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
    ScatterPoint p;
    p.label = "tool " + std::to_string(i) + " / office paper";
    p.group = groups[i % 3];
    p.x = 2.0 * std::cos(t), p.y = 1.5 * std::sin(t);
    const double a = 0.15 + 0.01 * static_cast<double>(i % 5), b = 0.08, angle = t;
    p.regions = {{p.x, p.y, a, b, angle}, {p.x, p.y, 1.62 * a, 1.62 * b, angle}};
    p.hollow = i == 4;
    plot.points.push_back(p);
  }
  return plot;
}

// Image pixel (column, row from the top) of a page position (origin bottom left).
Rgb pixel_at(const nibrig::test::RgbImage& img, double page_x, double page_y) {
  return img.at(static_cast<int>(std::floor(page_x)),
                static_cast<int>(std::floor(img.height - page_y)));
}

TEST(ReportScatterPlot, WritesAPngOfTheAskedSizeWithNothingAtTheBorder) {
  const auto dir = nibrig::test::scratch_dir("scatter_sizes");
  auto plot = sample_space();
  write_scatter_plot(plot, dir / "default.png");
  plot.size = {900, 900};
  write_scatter_plot(plot, dir / "square.png");
  plot.size = {640, 400};
  write_scatter_plot(plot, dir / "small.png");
  EXPECT_EQ(nibrig::test::png_header(dir / "default.png").width, 1200u);
  EXPECT_EQ(nibrig::test::png_header(dir / "default.png").height, 800u);
  EXPECT_EQ(nibrig::test::png_header(dir / "square.png").width, 900u);
  EXPECT_EQ(nibrig::test::png_header(dir / "square.png").height, 900u);
  EXPECT_EQ(nibrig::test::png_header(dir / "small.png").width, 640u);
  EXPECT_EQ(nibrig::test::png_header(dir / "small.png").height, 400u);
  // Only the figures: no temporary file is left beside them.
  EXPECT_EQ(test::names_in(dir).size(), 3u);
  for (const auto& name : test::names_in(dir)) test::expect_white_border(dir / name);
}

TEST(ReportScatterPlot, GroupsAtOppositeCornersColourOppositeCornersOfThePlot) {
  // Group A near the origin, group B near (10, 10), no labels or regions: colour A may appear
  // only in the lower left quarter of the plot, colour B only in the upper right one.
  ScatterPlot plot;
  plot.title = "Two corners";
  for (int i = 0; i < 3; ++i) {
    plot.points.push_back({"", 0.2 * i, 0.1 * i, "A", {}, false});
    plot.points.push_back({"", 10.0 - 0.2 * i, 10.0 - 0.1 * i, "B", {}, false});
  }
  const auto dir = nibrig::test::scratch_dir("scatter_corners");
  write_scatter_plot(plot, dir / "corners.png");
  const auto img = nibrig::test::decode_png(dir / "corners.png");
  // The plot box, to leave out the legend's swatches above it.
  const auto box = layout_scatter(plot).axes.box;
  const double mid_x = 0.5 * (box.x0 + box.x1), mid_y = 0.5 * (box.y0 + box.y1);
  const auto& palette = categorical_palette();
  int a_in = 0, a_out = 0, b_in = 0, b_out = 0;
  for (int row = static_cast<int>(img.height - box.y1) + 1; row < img.height - box.y0; ++row) {
    for (int col = static_cast<int>(box.x0) + 1; col < box.x1; ++col) {
      const double y = img.height - row - 0.5, x = col + 0.5;
      // Tolerance 2 per channel: the inside of a marker is its exact colour; its anti-aliased rim
      // is a blend that this excludes.
      if (nibrig::test::near(img.at(col, row), palette[0], 2)) (x < mid_x && y < mid_y ? a_in : a_out)++;
      if (nibrig::test::near(img.at(col, row), palette[1], 2)) (x > mid_x && y > mid_y ? b_in : b_out)++;
    }
  }
  // A marker of radius 4.5 px has about 50 pixels of its exact colour; three of them overlap.
  EXPECT_GT(a_in, 40);
  EXPECT_GT(b_in, 40);
  EXPECT_EQ(a_out, 0);
  EXPECT_EQ(b_out, 0);
}

TEST(ReportScatterPlot, EachMarkerShowsItsGroupColourWhereTheAxesPutIt) {
  const auto plot = sample_space();
  const auto dir = nibrig::test::scratch_dir("scatter_markers");
  write_scatter_plot(plot, dir / "space.png");
  const auto img = nibrig::test::decode_png(dir / "space.png");
  const auto f = layout_scatter(plot);
  const auto& palette = categorical_palette();
  for (std::size_t i = 0; i < plot.points.size(); ++i) {
    const double x = f.mapping.px(plot.points[i].x), y = f.mapping.py(plot.points[i].y);
    const Rgb group = palette[i % 3];
    // The 3×3 pixels around the centre lie well inside a 4.5 px disc (PLplot places to 0.1 px):
    // the group colour; for the hollow marker, white inside its ring.
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        const auto c = pixel_at(img, x + dx, y + dy);
        const Rgb expected = plot.points[i].hollow ? white : group;
        EXPECT_TRUE(nibrig::test::near(c, expected, 2)) << "point " << i << " at " << dx << "," << dy
                                                << ": " << c.r << "," << c.g << "," << c.b;
      }
    }
  }
  // The ring of the hollow marker is in its group colour: some pixel at about 3.5 px from the
  // centre (ring 1.6 px wide inside the 4.5 px radius) is close to it.
  const double hx = f.mapping.px(plot.points[4].x), hy = f.mapping.py(plot.points[4].y);
  int ring = 0;
  for (int k = 0; k < 16; ++k) {
    const double t = 2.0 * std::numbers::pi * k / 16;
    ring += nibrig::test::near(pixel_at(img, hx + 3.6 * std::cos(t), hy + 3.6 * std::sin(t)),
                       palette[4 % 3], 40);
  }
  EXPECT_GE(ring, 8);
}

// Walks from (x, y) along (ux, uy) in page pixels, from `from` px out to `to` px, and returns the
// middle of the first run of pixels close to `colour`, in px from the start; -1 if none.
double first_run(const nibrig::test::RgbImage& img, double x, double y, double ux, double uy, double from,
                 double to, Rgb colour) {
  double start = -1.0, end = -1.0;
  for (double d = from; d <= to; d += 0.25) {
    const bool hit = nibrig::test::near(pixel_at(img, x + d * ux, y + d * uy), colour, 60);
    if (hit && start < 0) start = d;
    if (hit) end = d;
    if (!hit && start >= 0) break;
  }
  return start < 0 ? -1.0 : 0.5 * (start + end);
}

TEST(ReportScatterPlot, OnEqualAxesAnEllipseOutlineLiesAtItsSemiAxes) {
  // Semi-axes 2 and 1, one ellipse level and one turned by 60°, and a far point giving the axes a
  // shape of their own (wider than tall in data, unlike the image).
  ScatterPlot plot;
  plot.title = "Ellipses";
  plot.points.push_back({"", 0.0, 0.0, "level", {{0.0, 0.0, 2.0, 1.0, 0.0}}, false});
  const double turn = std::numbers::pi / 3.0;
  plot.points.push_back({"", 7.0, 0.0, "turned", {{7.0, 0.0, 2.0, 1.0, turn}}, false});
  plot.points.push_back({"", 12.0, 1.0, "far", {}, false});
  const auto dir = nibrig::test::scratch_dir("scatter_ellipses");
  write_scatter_plot(plot, dir / "ellipses.png");
  const auto img = nibrig::test::decode_png(dir / "ellipses.png");
  const auto m = layout_scatter(plot).mapping;
  const auto& palette = categorical_palette();

  // Measured in the image alone: on equal axes the long semi-axis is twice the short one. The
  // outline (1.9 px, anti-aliased) is found to within a pixel at each end: 3 px on the ratio.
  const double cx = m.px(0.0), cy = m.py(0.0);
  const double along_x = first_run(img, cx, cy, 1.0, 0.0, 8.0, 600.0, palette[0]);
  const double along_y = first_run(img, cx, cy, 0.0, 1.0, 8.0, 600.0, palette[0]);
  ASSERT_GT(along_x, 0.0);
  ASSERT_GT(along_y, 0.0);
  EXPECT_NEAR(along_x, 2.0 * along_y, 3.0);

  // Against the axis mapping: the same number of pixels per unit on both axes, and the outline
  // at 2 and 1 units from the centre to within 1.5 px (half the outline and a pixel's rounding).
  const double per_unit_x = m.box.width() / (m.xmax - m.xmin);
  const double per_unit_y = m.box.height() / (m.ymax - m.ymin);
  EXPECT_NEAR(per_unit_x, per_unit_y, 1e-9 * per_unit_x);
  EXPECT_NEAR(along_x, 2.0 * per_unit_x, 1.5);
  EXPECT_NEAR(along_y, 1.0 * per_unit_y, 1.5);
  // The turned one: its long semi-axis points 60° up from +x, its short one 150°.
  const double tx = m.px(7.0), ty = m.py(0.0);
  const double long_axis =
      first_run(img, tx, ty, std::cos(turn), std::sin(turn), 8.0, 600.0, palette[1]);
  const double short_axis =
      first_run(img, tx, ty, std::cos(turn + std::numbers::pi / 2),
                std::sin(turn + std::numbers::pi / 2), 8.0, 600.0, palette[1]);
  EXPECT_NEAR(long_axis, 2.0 * per_unit_x, 1.5);
  EXPECT_NEAR(short_axis, 1.0 * per_unit_x, 1.5);
}

TEST(ReportScatterPlot, AxesHoldTheExactBoundingBoxOfATurnedEllipse) {
  // Semi-axes 3 and 1 at 30°: half-extents sqrt(9 cos² + sin²) = sqrt(7) and sqrt(3), less than
  // the 3 a box of the longer semi-axis would give. The axes reach just past them: by the outline's
  // width and the layout's 2 % step, at most 3 px.
  ScatterPlot plot;
  plot.title = "Bounding box";
  plot.equal_axes = false;
  plot.points.push_back({"", 0.0, 0.0, "", {{0.0, 0.0, 3.0, 1.0, std::numbers::pi / 6}}, false});
  const auto m = layout_scatter(plot).mapping;
  const double x_unit = (m.xmax - m.xmin) / m.box.width();
  const double y_unit = (m.ymax - m.ymin) / m.box.height();
  for (double edge : {m.xmax, -m.xmin}) {
    EXPECT_GE(edge, std::sqrt(7.0));
    EXPECT_LE(edge, std::sqrt(7.0) + 3.0 * x_unit);
  }
  for (double edge : {m.ymax, -m.ymin}) {
    EXPECT_GE(edge, std::sqrt(3.0));
    EXPECT_LE(edge, std::sqrt(3.0) + 3.0 * y_unit);
  }
}

TEST(ReportScatterPlot, TheLegendListsGroupsRegionStylesAndHollowOnlyWhenUsed) {
  auto plot = sample_space();
  std::vector<std::string> labels;
  for (const auto& e : layout_scatter(plot).legend) labels.push_back(e.label);
  EXPECT_EQ(labels, (std::vector<std::string>{"pencils", "printed nibs", "commercial styli", "68 %",
                                              "95 %", "placed from descriptors"}));
  for (auto& p : plot.points) p.hollow = false, p.regions.resize(1);
  labels.clear();
  for (const auto& e : layout_scatter(plot).legend) labels.push_back(e.label);
  EXPECT_EQ(labels,
            (std::vector<std::string>{"pencils", "printed nibs", "commercial styli", "68 %"}));
  // The region styles differ in width or dashes, so that they read apart in one colour.
  const auto st = detail::Style::for_size({});
  for (std::size_t k = 1; k < 4; ++k) {
    const auto a = detail::region_outline(k - 1, st), b = detail::region_outline(k, st);
    EXPECT_TRUE(a.width_px != b.width_px || a.dashes_px != b.dashes_px) << k;
  }
}

// Lagunas et al.'s 100 stimuli: a dense cloud of labelled points with regions.
ScatterPlot hundred_points() {
  ScatterPlot plot;
  plot.title = "One hundred stimuli";
  plot.region_labels = {"68 %", "95 %"};
  const char* groups[] = {"metal", "fabric", "plastic", "wood"};
  for (int i = 0; i < 100; ++i) {
    // A golden-angle spiral: evenly dense, crowded enough that not every label fits.
    const double r = std::sqrt(i + 0.5), t = 2.39996 * i;
    const double x = r * std::cos(t), y = 0.7 * r * std::sin(t);
    plot.points.push_back({"stimulus " + std::to_string(i),
                           x,
                           y,
                           groups[i % 4],
                           {{x, y, 0.25, 0.12, t}, {x, y, 0.4, 0.2, t}},
                           i % 10 == 0});
  }
  return plot;
}

bool overlap(const detail::Box& a, const detail::Box& b) {
  return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

TEST(ReportScatterPlot, AHundredLabelledPointsRenderWithoutLabelsOverlapping) {
  const auto plot = hundred_points();
  const auto dir = nibrig::test::scratch_dir("scatter_hundred");
  write_scatter_plot(plot, dir / "hundred.png");
  EXPECT_EQ(nibrig::test::png_header(dir / "hundred.png").width, 1200u);
  test::expect_white_border(dir / "hundred.png");

  // Beyond 40 points a label is either free of every other label and marker, or left out.
  const auto f = layout_scatter(plot);
  int placed = 0;
  for (std::size_t i = 0; i < f.labels.size(); ++i) {
    if (!f.labels[i].placed) continue;
    ++placed;
    const auto& b = f.labels[i].box;
    EXPECT_TRUE(b.x0 >= f.axes.box.x0 && b.x1 <= f.axes.box.x1 && b.y0 >= f.axes.box.y0 &&
                b.y1 <= f.axes.box.y1)
        << "label " << i << " leaves the plot";
    for (std::size_t j = 0; j < f.labels.size(); ++j) {
      const auto& q = f.label_requests[j];
      const double r = f.marker_radius;
      EXPECT_FALSE(overlap(b, {q.x - r, q.y - r, q.x + r, q.y + r})) << i << " covers marker " << j;
      if (j != i && f.labels[j].placed) {
        EXPECT_FALSE(overlap(b, f.labels[j].box)) << "labels " << i << " and " << j;
      }
    }
  }
  // Most still get their label: the spiral leaves room around the outer points.
  EXPECT_GE(placed, 50);
}

TEST(ReportScatterPlot, UpToFortyPointsAreAllLabelledEvenWhenCrowded) {
  auto plot = hundred_points();
  plot.points.resize(40);
  for (auto& p : plot.points) p.x *= 0.3, p.y *= 0.3;  // crowded: labels cannot all be free
  const auto f = layout_scatter(plot);
  for (std::size_t i = 0; i < f.labels.size(); ++i) EXPECT_TRUE(f.labels[i].placed) << i;
}

// The print sheet's space plot, a third of a page, had its stimuli's labels drawn over each other.
// There a crowded label is left out instead; the placed design and target are labelled always.
TEST(ReportScatterPlot, ASheetsSmallPlotLeavesOutCrowdedLabelsButNotThePlacedTools) {
  ScatterPlot plot;
  for (int i = 0; i < 15; ++i) {  // a 15-tool space, its tools crowded near the middle
    const double a = 2.4 * i, r = 0.05 + 0.02 * i;
    plot.points.push_back({"tool" + std::to_string(i) + "/office", r * std::cos(a), r * std::sin(a), "office", {}, false});
  }
  plot.points.push_back({"this design", 0.01, 0.02, "this design", {}, true});
  plot.points.push_back({"cryon/office (target)", -0.03, 0.0, "target", {}, true});
  plot.leave_out_crowded_labels = true;
  const detail::Style st = detail::Style::for_size({1600, 1000});
  const detail::Box sheet_corner{900, 60, 1560, 420};  // where the sheet puts it: 660 x 360 px
  const auto f = detail::layout_scatter(plot, st, sheet_corner);
  int placed = 0;
  for (std::size_t i = 0; i < f.labels.size(); ++i) {
    if (!f.labels[i].placed) continue;
    ++placed;
    for (std::size_t j = 0; j < f.labels.size(); ++j) {
      const auto& q = f.label_requests[j];
      const double r = f.marker_radius;
      if (i < 15) EXPECT_FALSE(overlap(f.labels[i].box, {q.x - r, q.y - r, q.x + r, q.y + r})) << i << " covers marker " << j;
      if (j != i && f.labels[j].placed && i < 15)
        EXPECT_FALSE(overlap(f.labels[i].box, f.labels[j].box)) << "labels " << i << " and " << j;
    }
  }
  EXPECT_TRUE(f.labels[15].placed && f.labels[16].placed) << "the design and the target are named";
  EXPECT_LT(placed, 17) << "crowded enough that some label had no free spot";
  EXPECT_GE(placed, 6) << "the outer tools still get theirs";

  plot.leave_out_crowded_labels = false;  // a full figure names every one of up to 40 points
  for (const auto& l : detail::layout_scatter(plot, st, sheet_corner).labels) EXPECT_TRUE(l.placed);
}

TEST(ReportScatterPlot, BadScatterPlotsAreRefused) {
  const auto refuse = [](const std::function<void(ScatterPlot&)>& spoil, const std::string& fault) {
    auto plot = sample_space();
    spoil(plot);
    test::expect_rejected([&](const fs::path& p) { write_scatter_plot(plot, p); }, plot.title,
                          fault);
  };
  refuse([](ScatterPlot& p) { p.points.clear(); }, "no points");
  refuse([](ScatterPlot& p) { p.points[2].x = std::nan(""); },
         "point 2 (tool 2 / office paper) x is not finite");
  refuse([](ScatterPlot& p) { p.points[3].y = INFINITY; }, "point 3 (tool 3 / office paper) y");
  refuse([](ScatterPlot& p) { p.points[1].regions[0].semi_axis_2 = -0.1; },
         "point 1 (tool 1 / office paper) region 0 semi_axis_2 = -0.100000 is negative");
  refuse([](ScatterPlot& p) { p.points[0].regions[1].semi_axis_1 = INFINITY; },
         "region 1 semi_axis_1 is not finite");
  refuse([](ScatterPlot& p) { p.points[5].regions[0].centre_y = std::nan(""); },
         "point 5 (tool 5 / office paper) region 0 centre_y is not finite");
  refuse([](ScatterPlot& p) { p.points[6].regions[1].angle_rad = INFINITY; },
         "region 1 angle_rad is not finite");
  refuse([](ScatterPlot& p) { p.region_labels = {"68 %"}; },
         "point 0 (tool 0 / office paper) region 1 has no legend text");
  refuse([](ScatterPlot& p) { p.size = {40, 800}; }, "image size 40x800");
}

TEST(ReportScatterPlot, RegionsNeedNoLegendTextWhenNoneIsGiven) {
  auto plot = sample_space();
  plot.region_labels.clear();
  const auto dir = nibrig::test::scratch_dir("scatter_no_region_labels");
  write_scatter_plot(plot, dir / "plot.png");
  for (const auto& e : layout_scatter(plot).legend)
    EXPECT_NE(e.kind, detail::LegendEntry::Kind::region) << e.label;
}

TEST(ReportScatterPlot, ThreadsDrawingAtOnceGetTheBytesOfDrawingInTurn) {
  const auto dir = nibrig::test::scratch_dir("scatter_threads");
  const auto plot = sample_space();
  const auto line =
      LinePlot{{{"a", {0.0, 1.0, 2.0}, {1.0, 0.5, 2.0}, {}, {}}}, "lines", "", "", false, {}};
  write_scatter_plot(plot, dir / "scatter.png");
  write_line_plot(line, dir / "line.png");
  std::vector<std::thread> threads;
  std::vector<std::string> errors(4);
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&, t] {
      try {
        const auto name = dir / ("thread_" + std::to_string(t) + ".png");
        if (t % 2 == 0) write_scatter_plot(plot, name);
        if (t % 2 == 1) write_line_plot(line, name);
      } catch (const std::exception& e) {
        errors[static_cast<std::size_t>(t)] = e.what();
      }
    });
  }
  for (auto& th : threads) th.join();
  for (int t = 0; t < 4; ++t) {
    EXPECT_EQ(errors[static_cast<std::size_t>(t)], "");
    EXPECT_EQ(test::read_bytes(dir / ("thread_" + std::to_string(t) + ".png")),
              test::read_bytes(dir / (t % 2 == 0 ? "scatter.png" : "line.png")))
        << "thread " << t;
  }
}

}  // namespace
}  // namespace nibrig::ui::report
