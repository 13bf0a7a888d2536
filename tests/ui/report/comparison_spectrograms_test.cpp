// The comparison figure read back as pixels: three heat-map panels side by side, the measured and
// simulated levels where they were put, the difference on its own scale centred on 0 dB.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tests/support/test_paths.hpp"
#include "tests/ui/report/figure_checks.hpp"
#include "tests/ui/report/png_reader.hpp"
#include "ui/report/colour_maps.hpp"
#include "ui/report/figures.hpp"

namespace nibrig::ui::report {
namespace {

namespace fs = std::filesystem;

// 40 times × 100 frequencies; measured is loud (0 dB) in frequencies 20-29 and 60 dB down
// elsewhere, simulated loud in 60-69 instead.
ComparisonSpectrograms two_stripes() {
  ComparisonSpectrograms f;
  for (int i = 0; i < 40; ++i) f.x.push_back(0.1 * i);
  for (int k = 0; k < 100; ++k) f.y.push_back(10.0 * k);
  f.measured_db.assign(100, std::vector<double>(40, -60.0));
  f.simulated_db = f.measured_db;
  for (int k = 20; k < 30; ++k) f.measured_db[k].assign(40, 0.0);
  for (int k = 60; k < 70; ++k) f.simulated_db[k].assign(40, 0.0);
  f.title = "vero2 on office";
  f.x_label = "time (s)";
  f.y_label = "frequency (Hz)";
  return f;
}

bool is_viridis(Rgb c, int index) { return nibrig::test::near(c, viridis()[index], 2); }
bool is_map_colour(Rgb c) {
  return is_viridis(c, 0) || is_viridis(c, 255) || is_viridis(c, 127) || is_viridis(c, 128);
}

// Column runs where at least a quarter of the pixels are the figure's cell colours: the panels
// (colour bars hold each colour for a pixel or two of their height only).
std::vector<std::pair<int, int>> panel_columns(const nibrig::test::RgbImage& img) {
  std::vector<std::pair<int, int>> runs;
  bool inside = false;
  for (int x = 0; x < img.width; ++x) {
    int count = 0;
    for (int y = 0; y < img.height; ++y) count += is_map_colour(img.at(x, y));
    const bool map = count > img.height / 4;
    if (map && !inside) runs.push_back({x, x});
    if (map) runs.back().second = x;
    inside = map;
  }
  return runs;
}

// Fraction of the panel's height (0 at its bottom) of the middle of the rows of `index`'s colour
// in column x.
double colour_height(const nibrig::test::RgbImage& img, int x, int index) {
  int top = img.height, bottom = -1, first = img.height, last = -1;
  for (int y = 0; y < img.height; ++y) {
    if (is_map_colour(img.at(x, y))) first = std::min(first, y), last = std::max(last, y);
    if (is_viridis(img.at(x, y), index)) top = std::min(top, y), bottom = std::max(bottom, y);
  }
  if (bottom < 0 || last <= first) return -1.0;
  return (last - 0.5 * (top + bottom)) / static_cast<double>(last - first);
}

TEST(ReportComparisonSpectrograms, ThreePanelsShowMeasuredSimulatedAndTheirDifference) {
  const auto dir = nibrig::test::scratch_dir("report_comparison");
  const auto png = dir / "comparison.png";
  write_comparison_spectrograms(two_stripes(), png);
  EXPECT_EQ(nibrig::test::png_header(png).width, 2100u);
  test::expect_white_border(png);
  const auto img = nibrig::test::decode_png(png);
  const auto panels = panel_columns(img);
  ASSERT_EQ(panels.size(), 3u) << "measured | simulated | difference";
  for (const auto& [x0, x1] : panels)
    EXPECT_GT(x1 - x0, img.width / 6) << "each panel takes most of its third of the width";
  const auto centre = [&](int k) { return (panels[k].first + panels[k].second) / 2; };
  // Frequencies 20-29 of -5..995 Hz centre at 0.25 of the height, 60-69 at 0.65; 0.02 is 10 px of
  // about 500, room for anti-aliased edges and the frame.
  EXPECT_NEAR(colour_height(img, centre(0), 255), 0.25, 0.02) << "measured's loud stripe";
  EXPECT_NEAR(colour_height(img, centre(1), 255), 0.65, 0.02) << "simulated's loud stripe";
  // The difference: +60 dB shows as the top of its ±20 dB scale where simulated is loud, -60 dB
  // as the bottom where measured is, and 0 dB in the middle colour elsewhere.
  EXPECT_NEAR(colour_height(img, centre(2), 255), 0.65, 0.02);
  EXPECT_NEAR(colour_height(img, centre(2), 0), 0.25, 0.02);
  const double middle =
      std::max(colour_height(img, centre(2), 127), colour_height(img, centre(2), 128));
  EXPECT_GT(middle, 0.0) << "equal levels show as the middle colour";
}

TEST(ReportComparisonSpectrograms, RefusesMismatchedOrBadInput) {
  auto f = two_stripes();
  f.simulated_db.pop_back();
  test::expect_rejected([&](const fs::path& p) { write_comparison_spectrograms(f, p); }, f.title,
                        "z has 99 rows");
  f = two_stripes();
  f.measured_db[3][4] = std::nan("");
  test::expect_rejected([&](const fs::path& p) { write_comparison_spectrograms(f, p); }, f.title,
                        "z[3][4] is not finite");
  f = two_stripes();
  f.dynamic_range_db = 0.0;
  test::expect_rejected([&](const fs::path& p) { write_comparison_spectrograms(f, p); }, f.title,
                        "dynamic_range_db");
}

}  // namespace
}  // namespace nibrig::ui::report
