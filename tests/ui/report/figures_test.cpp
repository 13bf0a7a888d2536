// The report figures as files: valid PNGs of the asked size, cells where their edges say, colours
// from the colour scale, nothing at the image borders, bad input refused without touching the
// target, and no PLplot state carried from one figure (or from the caller) into the next.
#include "ui/report/figures.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <plplot/plplot.h>
#include <stdlib.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <iterator>
#include <thread>

#include "tests/support/test_paths.hpp"
#include "tests/ui/report/figure_checks.hpp"
#include "tests/ui/report/png_reader.hpp"
#include "ui/report/colour_maps.hpp"

namespace nibrig::ui::report {
namespace {

using test::expect_rejected;
using test::expect_white_border;
using test::names_in;
using ::testing::AllOf;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

HeatMap sample_heat_map() {
  HeatMap map;
  map.x = {0.0, 1.0, 3.0, 7.0, 15.0};  // non-uniform: edges -0.5, 0.5, 2, 5, 11, 19
  map.y = {10.0, 20.0, 40.0};          // edges 5, 15, 30, 50
  map.z = {{0, 0, 0, 0, 0}, {0, 0, 0, 1, 0}, {0.5, 0, 0, 0, 0}};
  map.title = "Known pattern";
  map.x_label = "frequency (Hz)";
  map.y_label = "speed (mm/s)";
  map.colour_label = "amplitude (m/s#u2#d)";
  return map;
}

IntervalChart sample_chart(std::size_t bars, bool long_labels = true) {
  IntervalChart chart;
  chart.title = "Coulomb friction per tool and surface";
  chart.value_label = "#gm";
  chart.reference_band = std::make_pair(0.13, 0.33);
  chart.reference_label = "range reported in the paper (0.13-0.33)";
  const char* surfaces[] = {"office paper", "screen protector", "sketch paper"};
  for (std::size_t i = 0; i < bars; ++i) {
    const double mu = 0.12 + 0.25 * std::fmod(i * 0.618, 1.0);
    const std::string tool = (long_labels ? "printed VeroClear nib " : "nib ") + std::to_string(i);
    chart.bars.push_back({tool + " / " + (long_labels ? surfaces[i % 3] : "paper"), mu, mu - 0.02,
                          mu + 0.03, surfaces[i % 3]});
  }
  return chart;
}

LinePlot sample_line_plot(std::size_t curves = 3) {
  LinePlot plot;
  plot.title = "Spectra by speed";
  plot.x_label = "frequency (Hz)";
  plot.y_label = "amplitude (m/s#u2#d)";
  plot.log_y = true;
  for (std::size_t c = 0; c < curves; ++c) {
    LineSeries s;
    s.label = std::to_string(20 * (c + 1)) + " mm/s";
    for (int i = 0; i < 200; ++i) {
      s.x.push_back(5.0 * i);
      s.y.push_back((c + 1) * 1e-2 * std::exp(-std::pow((5.0 * i - 100.0 * (c + 1)) / 80.0, 2)) +
                    1e-4);
    }
    if (c == 0) {
      for (double y : s.y) s.y_low.push_back(0.7 * y), s.y_high.push_back(1.4 * y);
    }
    plot.series.push_back(s);
  }
  return plot;
}

TEST(ReportFigures, EachKindWritesAPngOfTheAskedSize) {
  const auto dir = nibrig::test::scratch_dir("report_sizes");
  write_heat_map(sample_heat_map(), dir / "heat.png");
  write_interval_chart(sample_chart(8, false), dir / "chart.png");
  write_line_plot(sample_line_plot(), dir / "lines.png");
  for (const char* name : {"heat.png", "chart.png", "lines.png"}) {
    const auto header = nibrig::test::png_header(dir / name);
    EXPECT_EQ(header.width, 1200u) << name;
    EXPECT_EQ(header.height, 800u) << name;
  }

  auto map = sample_heat_map();
  map.size = {640, 480};
  auto chart = sample_chart(8, false);
  chart.size = {900, 700};
  auto plot = sample_line_plot();
  plot.size = {2000, 1000};
  write_heat_map(map, dir / "heat_small.png");
  write_interval_chart(chart, dir / "chart_other.png");
  write_line_plot(plot, dir / "lines_large.png");
  EXPECT_EQ(nibrig::test::png_header(dir / "heat_small.png").width, 640u);
  EXPECT_EQ(nibrig::test::png_header(dir / "heat_small.png").height, 480u);
  EXPECT_EQ(nibrig::test::png_header(dir / "chart_other.png").width, 900u);
  EXPECT_EQ(nibrig::test::png_header(dir / "chart_other.png").height, 700u);
  EXPECT_EQ(nibrig::test::png_header(dir / "lines_large.png").width, 2000u);
  EXPECT_EQ(nibrig::test::png_header(dir / "lines_large.png").height, 1000u);
  // An interval chart is as large as asked or larger: labels too long for the height heighten it.
  auto long_labels = sample_chart(8);
  long_labels.size = {900, 500};
  write_interval_chart(long_labels, dir / "chart_long_labels.png");
  EXPECT_EQ(nibrig::test::png_header(dir / "chart_long_labels.png").width, 900u);
  EXPECT_GT(nibrig::test::png_header(dir / "chart_long_labels.png").height, 500u);
  // stb_image, an independent decoder, reads every one of them whole.
  for (const auto& name : names_in(dir)) {
    const auto img = nibrig::test::decode_png(dir / name);
    EXPECT_EQ(static_cast<std::uint32_t>(img.width), nibrig::test::png_header(dir / name).width);
  }
  // Only the figures: no temporary file is left beside them.
  EXPECT_EQ(names_in(dir).size(), 7u);
}

TEST(ReportFigures, NothingReachesTheImageBorder) {
  const auto dir = nibrig::test::scratch_dir("report_borders");
  auto small_map = sample_heat_map();
  small_map.size = {480, 320};
  auto many_curves = sample_line_plot(12);
  many_curves.log_y = false;
  write_heat_map(sample_heat_map(), dir / "heat.png");
  write_heat_map(small_map, dir / "heat_small.png");
  write_interval_chart(sample_chart(5), dir / "chart.png");
  write_line_plot(sample_line_plot(), dir / "lines.png");
  write_line_plot(many_curves, dir / "many.png");
  // Texts longer than the image is wide are set smaller rather than cut off.
  auto long_texts = sample_line_plot();
  long_texts.title =
      std::string(30, 'W') + " a title far longer than the figure is wide " + std::string(30, 'M');
  long_texts.x_label = std::string(150, 'm');
  long_texts.y_label = std::string(80, 'W');
  write_line_plot(long_texts, dir / "long_texts.png");
  auto long_colour_label = sample_heat_map();
  long_colour_label.colour_label = std::string(90, 'W');
  write_heat_map(long_colour_label, dir / "long_colour_label.png");
  EXPECT_EQ(names_in(dir).size(), 7u);
  for (const auto& name : names_in(dir)) expect_white_border(dir / name);
}

TEST(ReportFigures, DegenerateButValidInputsStillDraw) {
  // One cell, one point, one bar, constant values: nothing to divide by zero, still a figure.
  const auto dir = nibrig::test::scratch_dir("report_degenerate");
  HeatMap one_cell;
  one_cell.x = {440.0};
  one_cell.y = {0.1};
  one_cell.z = {{3.0}};
  one_cell.title = "One cell";
  write_heat_map(one_cell, dir / "one_cell.png");
  one_cell.log_colour = true;
  write_heat_map(one_cell, dir / "one_cell_db.png");
  auto flat = sample_heat_map();
  for (auto& row : flat.z) row.assign(row.size(), 2.5);
  write_heat_map(flat, dir / "flat.png");

  LinePlot one_point;
  one_point.series.push_back({"only", {2.0}, {0.2}, {0.15}, {0.3}});
  write_line_plot(one_point, dir / "one_point.png");
  one_point.log_y = true;
  write_line_plot(one_point, dir / "one_point_log.png");

  IntervalChart one_bar;
  one_bar.bars.push_back({"", 0.2, 0.2, 0.2, ""});
  write_interval_chart(one_bar, dir / "one_bar.png");

  for (const auto& name : names_in(dir)) {
    EXPECT_EQ(nibrig::test::png_header(dir / name).width, 1200u) << name;
    expect_white_border(dir / name);
  }
  EXPECT_EQ(names_in(dir).size(), 6u);
}

TEST(ReportIntervalChart, NinetyBarsWidenTheImageSoEveryLabelHasRoom) {
  const auto dir = nibrig::test::scratch_dir("report_ninety");
  const auto chart = sample_chart(90);
  write_interval_chart(chart, dir / "chart.png");
  const auto header = nibrig::test::png_header(dir / "chart.png");
  // About 20 px per bar at the default size (a label's line height), so well over 1200 px.
  EXPECT_GE(header.width, 90u * 20u);
  EXPECT_GE(header.height, 800u);
  expect_white_border(dir / "chart.png");

  // Each bar's upright label is a column of ink under the plot: count the separate runs of inked
  // columns in a row crossing the labels just under the axis. Touching labels would merge runs.
  const auto img = nibrig::test::decode_png(dir / "chart.png");
  int best_runs = 0;
  for (int y = img.height / 2; y < img.height; ++y) {
    int runs = 0;
    bool inked = false;
    for (int x = 0; x < img.width; ++x) {
      const auto c = img.at(x, y);
      const bool ink = c.r < 160 && c.g < 160 && c.b < 160;
      if (ink && !inked) ++runs;
      inked = ink;
    }
    best_runs = std::max(best_runs, runs);
  }
  EXPECT_GE(best_runs, 90);
}

// The heat map's cells (t = 0, 0.5, 1 of the colour scale) in a decoded image: finds the map as the
// columns and rows mostly made of those colours (the colour bar has each of them for only a pixel
// or two of its height), then the box of the bright cell and the colour in the middle cell.
struct CellCheck {
  int map_x0, map_x1, map_y0, map_y1;  // inclusive, rows from the top
  int bright_x0, bright_x1, bright_y0, bright_y1;
};

CellCheck find_cells(const nibrig::test::RgbImage& img) {
  const auto& v = viridis();
  const auto is_map_colour = [&](Rgb c) {
    return nibrig::test::near(c, v[0], 2) || nibrig::test::near(c, v[255], 2) || nibrig::test::near(c, v[128], 2) ||
           nibrig::test::near(c, v[127], 2);
  };
  CellCheck out{img.width, -1, img.height, -1, img.width, -1, img.height, -1};
  for (int x = 0; x < img.width; ++x) {
    int count = 0;
    for (int y = 0; y < img.height; ++y) count += is_map_colour(img.at(x, y));
    if (count > img.height / 4)
      out.map_x0 = std::min(out.map_x0, x), out.map_x1 = std::max(out.map_x1, x);
  }
  for (int y = 0; y < img.height; ++y) {
    int count = 0;
    for (int x = out.map_x0; x <= out.map_x1; ++x) count += is_map_colour(img.at(x, y));
    if (count > (out.map_x1 - out.map_x0) / 4)
      out.map_y0 = std::min(out.map_y0, y), out.map_y1 = std::max(out.map_y1, y);
  }
  for (int y = out.map_y0; y <= out.map_y1; ++y) {
    for (int x = out.map_x0; x <= out.map_x1; ++x) {
      if (nibrig::test::near(img.at(x, y), v[255], 2)) {
        out.bright_x0 = std::min(out.bright_x0, x), out.bright_x1 = std::max(out.bright_x1, x);
        out.bright_y0 = std::min(out.bright_y0, y), out.bright_y1 = std::max(out.bright_y1, y);
      }
    }
  }
  return out;
}

// Checks the cell layout of sample_heat_map: the bright cell z[1][3] spans x 5..11 of -0.5..19 and
// y 15..30 of 5..50; the middle cell z[2][0] (x -0.5..0.5, y 30..50) shows the middle colour.
// 3 px tolerance: the frame line (1.6 px) covers the map's outermost pixel, cell edges are
// anti-aliased over a pixel, and PLplot rounds positions to 0.1 px.
void expect_known_pattern(const fs::path& png) {
  const auto img = nibrig::test::decode_png(png);
  const auto c = find_cells(img);
  ASSERT_GT(c.map_x1 - c.map_x0, img.width / 2) << "heat map not found in " << png;
  ASSERT_GT(c.map_y1 - c.map_y0, img.height / 2) << "heat map not found in " << png;
  const double w = c.map_x1 - c.map_x0 + 1, h = c.map_y1 - c.map_y0 + 1;
  const auto px = [&](double x) { return c.map_x0 + (x + 0.5) / 19.5 * w; };
  const auto py = [&](double y) { return c.map_y0 + (50.0 - y) / 45.0 * h; };  // rows grow down
  EXPECT_NEAR(c.bright_x0, px(5.0), 3.0);
  EXPECT_NEAR(c.bright_x1 + 1, px(11.0), 3.0);
  EXPECT_NEAR(c.bright_y0, py(30.0), 3.0);
  EXPECT_NEAR(c.bright_y1 + 1, py(15.0), 3.0);
  const auto middle = img.at(static_cast<int>(px(0.0)), static_cast<int>(py(40.0)));
  EXPECT_TRUE(nibrig::test::near(middle, viridis()[128], 2) || nibrig::test::near(middle, viridis()[127], 2))
      << "middle cell is " << middle.r << "," << middle.g << "," << middle.b;
  const auto background = img.at(static_cast<int>(px(13.0)), static_cast<int>(py(10.0)));
  EXPECT_TRUE(nibrig::test::near(background, viridis()[0], 2));
}

TEST(ReportHeatMap, CellsSitBetweenTheMidpointsOfTheirNeighbours) {
  const auto dir = nibrig::test::scratch_dir("report_pattern");
  write_heat_map(sample_heat_map(), dir / "linear.png");
  expect_known_pattern(dir / "linear.png");
}

TEST(ReportHeatMap, DecibelScaleIsReMaxAndClampsAtMinus60) {
  // Background at -80 dB shows as -60 dB (the bottom colour); -30 dB sits mid-scale.
  auto map = sample_heat_map();
  map.log_colour = true;
  for (auto& row : map.z) {
    for (double& v : row) v = 1e-4;
  }
  map.z[1][3] = 2.0;                                 // the maximum: 0 dB
  map.z[2][0] = 2.0 * std::pow(10.0, -30.0 / 20.0);  // -30 dB re max
  const auto dir = nibrig::test::scratch_dir("report_decibel");
  write_heat_map(map, dir / "db.png");
  expect_known_pattern(dir / "db.png");
}

TEST(ReportHeatMap, MoreCellsThanPixelsStillShowANarrowPeak) {
  // 6000 columns on a plot about 900 px wide: one bright column must survive the merge.
  HeatMap map;
  for (int i = 0; i < 6000; ++i) map.x.push_back(i);
  map.y = {1.0, 2.0};
  map.z.assign(2, std::vector<double>(6000, 0.0));
  map.z[0][4500] = map.z[1][4500] = 1.0;
  map.title = "Narrow peak";
  const auto dir = nibrig::test::scratch_dir("report_merge");
  write_heat_map(map, dir / "peak.png");
  const auto img = nibrig::test::decode_png(dir / "peak.png");
  const auto c = find_cells(img);
  ASSERT_LE(c.bright_x0, c.bright_x1) << "the peak vanished";
  const double expected = c.map_x0 + (4500.0 + 0.5) / 6000.0 * (c.map_x1 - c.map_x0 + 1);
  EXPECT_NEAR(0.5 * (c.bright_x0 + c.bright_x1), expected, 3.0);
}

TEST(ReportFigures, BadHeatMapsAreRefused) {
  const auto refuse = [](const std::function<void(HeatMap&)>& spoil, const std::string& fault) {
    auto map = sample_heat_map();
    spoil(map);
    expect_rejected([&](const fs::path& p) { write_heat_map(map, p); }, map.title, fault);
  };
  refuse([](HeatMap& m) { m.x.clear(); }, "x is empty");
  refuse([](HeatMap& m) { m.z.pop_back(); }, "z has 2 rows but y has 3");
  refuse([](HeatMap& m) { m.z[1].push_back(0.0); }, "z row 1 has 6 values but x has 5");
  refuse([](HeatMap& m) { m.z[1][2] = std::nan(""); }, "z[1][2] is not finite");
  refuse([](HeatMap& m) { m.z[0][0] = INFINITY; }, "z[0][0] is not finite");
  refuse([](HeatMap& m) { m.x[2] = 1.0; }, "x is not strictly increasing at index 2");
  refuse([](HeatMap& m) { m.y[0] = std::nan(""); }, "y[0] is not finite");
  refuse([](HeatMap& m) { m.log_colour = true, m.z[0][1] = -1.0; }, "z[0][1] = -1");
  refuse(
      [](HeatMap& m) {
        m.log_colour = true;
        for (auto& row : m.z) row.assign(row.size(), 0.0);
      },
      "at least one positive z");
  refuse([](HeatMap& m) { m.size = {0, 800}; }, "image size 0x800");
}

TEST(ReportFigures, BadIntervalChartsAreRefused) {
  const auto refuse = [](const std::function<void(IntervalChart&)>& spoil,
                         const std::string& fault) {
    auto chart = sample_chart(6);
    spoil(chart);
    expect_rejected([&](const fs::path& p) { write_interval_chart(chart, p); }, chart.title, fault);
  };
  refuse([](IntervalChart& c) { c.bars.clear(); }, "no bars");
  refuse([](IntervalChart& c) { c.bars[2].value = std::nan(""); },
         "bar 2 (printed VeroClear nib 2 / sketch paper) value is not finite");
  refuse([](IntervalChart& c) { c.bars[3].high = -INFINITY; }, "bar 3");
  refuse([](IntervalChart& c) { std::swap(c.bars[1].low, c.bars[1].high); }, "above high");
  refuse([](IntervalChart& c) { c.reference_band = std::make_pair(0.33, 0.13); }, "reference band");
}

TEST(ReportFigures, BadLinePlotsAreRefused) {
  const auto refuse = [](const std::function<void(LinePlot&)>& spoil, const std::string& fault) {
    auto plot = sample_line_plot();
    spoil(plot);
    expect_rejected([&](const fs::path& p) { write_line_plot(plot, p); }, plot.title, fault);
  };
  refuse([](LinePlot& p) { p.series.clear(); }, "no series");
  refuse([](LinePlot& p) { p.series[1].y.pop_back(); },
         "series 1 (40 mm/s) has 200 x but 199 y values");
  refuse([](LinePlot& p) { p.series[0].y_high.clear(); }, "band of 200 low and 0 high");
  refuse([](LinePlot& p) { p.series[2].y[7] = 0.0; },
         "y[7] = 0.000000 cannot be shown on a log axis");
  refuse([](LinePlot& p) { p.series[2].x[1] = std::nan(""); },
         "series 2 (60 mm/s) x[1] is not finite");
  refuse([](LinePlot& p) { p.series[0].y_low[4] = 10.0; }, "band at point 4 has y_low");
  refuse([](LinePlot& p) { p.series[0].x.clear(); }, "series 0 (20 mm/s) has no points");
}

TEST(ReportFigures, AnUnwritableFolderIsAnExceptionNotAnExit) {
  // PLplot ends the process when it cannot open its output; the figure must find out first.
  const auto dir = nibrig::test::scratch_dir("report_unwritable");
  try {
    write_line_plot(sample_line_plot(), dir / "missing" / "lines.png");
    ADD_FAILURE() << "wrote into a folder that does not exist";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), AllOf(HasSubstr("lines.png"), HasSubstr("No such file or directory")));
  }
  EXPECT_TRUE(names_in(dir).empty());
}

TEST(ReportFigures, AMissingPngcairoDriverIsReported) {
  // PLplot looks for drivers in $PLPLOT_DRV_DIR; pointing it at an empty folder is a machine
  // without plplot-driver-cairo. (PLplot itself would end the process on finding no driver at all.)
  const auto dir = nibrig::test::scratch_dir("report_no_driver");
  const auto drivers = dir / "drivers";
  fs::create_directories(drivers);
  const char* old = std::getenv("PLPLOT_DRV_DIR");
  const std::string saved = old != nullptr ? old : "";
  setenv("PLPLOT_DRV_DIR", drivers.c_str(), 1);
  std::string message;
  try {
    write_heat_map(sample_heat_map(), dir / "heat.png");
  } catch (const std::runtime_error& e) {
    message = e.what();
  }
  if (old != nullptr) {
    setenv("PLPLOT_DRV_DIR", saved.c_str(), 1);
  } else {
    unsetenv("PLPLOT_DRV_DIR");
  }
  EXPECT_THAT(message, AllOf(HasSubstr("pngcairo"), HasSubstr("plplot-driver-cairo")));
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"drivers"});
  // With the real driver folder back, figures work again.
  write_heat_map(sample_heat_map(), dir / "heat.png");
  EXPECT_EQ(nibrig::test::png_header(dir / "heat.png").width, 1200u);
}

TEST(ReportFigures, FiguresDoNotLeakStateIntoOneAnother) {
  // Heat map (colour map 1, images) and line plot (log axis, translucent bands, many colours), each
  // drawn after the other: the bytes must not depend on what came before.
  const auto dir = nibrig::test::scratch_dir("report_state");
  const auto map = sample_heat_map();
  const auto plot = sample_line_plot(8);
  write_heat_map(map, dir / "map_first.png");
  write_line_plot(plot, dir / "plot_after_map.png");
  write_interval_chart(sample_chart(30), dir / "chart.png");
  write_heat_map(map, dir / "map_after_plot.png");
  write_line_plot(plot, dir / "plot_again.png");
  EXPECT_EQ(test::read_bytes(dir / "map_first.png"), test::read_bytes(dir / "map_after_plot.png"));
  EXPECT_EQ(test::read_bytes(dir / "plot_after_map.png"), test::read_bytes(dir / "plot_again.png"));
  EXPECT_NE(test::read_bytes(dir / "map_first.png"), test::read_bytes(dir / "plot_again.png"));
}

TEST(ReportFigures, TheCallersOwnPlplotSettingsDoNotReachAFigure) {
  const auto dir = nibrig::test::scratch_dir("report_caller_state");
  write_line_plot(sample_line_plot(), dir / "clean.png");
  // A program that uses PLplot itself: its current stream has a black background, big characters,
  // a dashed line style and a different colour map 1.
  PLINT own = 0;
  plmkstrm(&own);
  plscolbg(0, 0, 0);
  plschr(0.0, 3.0);
  plwidth(7.0);
  plscmap1n(16);
  write_line_plot(sample_line_plot(), dir / "after_caller.png");
  PLINT current = -1;
  plgstrm(&current);
  EXPECT_EQ(current, own) << "the figure did not hand back the caller's stream";
  plend1();
  EXPECT_EQ(test::read_bytes(dir / "clean.png"), test::read_bytes(dir / "after_caller.png"));
}

TEST(ReportFigures, ThreadsDrawingAtOnceGetTheBytesOfDrawingInTurn) {
  const auto dir = nibrig::test::scratch_dir("report_threads");
  const auto map = sample_heat_map();
  const auto chart = sample_chart(12);
  const auto plot = sample_line_plot();
  write_heat_map(map, dir / "map.png");
  write_interval_chart(chart, dir / "chart.png");
  write_line_plot(plot, dir / "plot.png");
  std::vector<std::thread> threads;
  std::vector<std::string> errors(6);
  for (int t = 0; t < 6; ++t) {
    threads.emplace_back([&, t] {
      try {
        const auto name = dir / ("thread_" + std::to_string(t) + ".png");
        if (t % 3 == 0) write_heat_map(map, name);
        if (t % 3 == 1) write_interval_chart(chart, name);
        if (t % 3 == 2) write_line_plot(plot, name);
      } catch (const std::exception& e) {
        errors[static_cast<std::size_t>(t)] = e.what();
      }
    });
  }
  for (auto& th : threads) th.join();
  const char* reference[] = {"map.png", "chart.png", "plot.png"};
  for (int t = 0; t < 6; ++t) {
    EXPECT_EQ(errors[static_cast<std::size_t>(t)], "");
    EXPECT_EQ(test::read_bytes(dir / ("thread_" + std::to_string(t) + ".png")),
              test::read_bytes(dir / reference[t % 3]))
        << "thread " << t;
  }
  EXPECT_EQ(names_in(dir).size(), 9u);  // no temporary left behind
}

}  // namespace
}  // namespace nibrig::ui::report
