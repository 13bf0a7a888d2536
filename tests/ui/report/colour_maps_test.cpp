// The colour tables: viridis as published (a mistyped entry would show as a jump in lightness),
// and a categorical palette that shows on white.
#include "ui/report/colour_maps.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <tuple>

namespace nibrig::ui::report {
namespace {

double channel_linear(int c) {
  const double v = c / 255.0;
  return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

double relative_luminance(Rgb c) {
  return 0.2126 * channel_linear(c.r) + 0.7152 * channel_linear(c.g) + 0.0722 * channel_linear(c.b);
}

// CIE L* (0-100) of an sRGB colour.
double lightness(Rgb c) {
  const double y = relative_luminance(c);
  const double f = y > 216.0 / 24389.0 ? std::cbrt(y) : (24389.0 / 27.0 * y + 16.0) / 116.0;
  return 116.0 * f - 16.0;
}

TEST(ColourMaps, ViridisEndsAtItsPublishedColours) {
  // #440154 and #FDE725 are viridis's documented end points.
  const auto& v = viridis();
  EXPECT_EQ(std::tie(v.front().r, v.front().g, v.front().b), std::make_tuple(0x44, 0x01, 0x54));
  EXPECT_EQ(std::tie(v.back().r, v.back().g, v.back().b), std::make_tuple(0xFD, 0xE7, 0x25));
}

TEST(ColourMaps, ViridisLightnessRisesInEvenSteps) {
  // Perceptual uniformity: L* rises monotonically and nearly linearly. Entries are rounded to
  // 8 bits, which moves L* by up to about 0.2, so single steps may tie; over 8 entries L* must
  // rise, and no 8-entry step may be more than twice the average one (a mistyped digit makes a
  // spike).
  const auto& v = viridis();
  const double average = (lightness(v[255]) - lightness(v[0])) / 255.0 * 8.0;
  EXPECT_GT(average, 1.0);
  for (std::size_t i = 0; i + 8 < v.size(); ++i) {
    const double step = lightness(v[i + 8]) - lightness(v[i]);
    EXPECT_GT(step, 0.3 * average) << "entries " << i << " to " << i + 8;
    EXPECT_LT(step, 2.0 * average) << "entries " << i << " to " << i + 8;
  }
  for (std::size_t i = 0; i + 1 < v.size(); ++i) {
    EXPECT_GT(lightness(v[i + 1]), lightness(v[i]) - 0.3) << "entry " << i;
  }
}

TEST(ColourMaps, ViridisAtPicksTheNearestEntryAndClamps) {
  const auto& v = viridis();
  EXPECT_EQ(viridis_at(0.0).r, v[0].r);
  EXPECT_EQ(viridis_at(1.0).g, v[255].g);
  EXPECT_EQ(viridis_at(2.0).b, v[255].b);
  EXPECT_EQ(viridis_at(-1.0).b, v[0].b);
  EXPECT_EQ(viridis_at(128.0 / 255.0).g, v[128].g);
}

TEST(ColourMaps, CategoricalColoursAreDistinctAndShowOnWhite) {
  std::set<std::tuple<int, int, int>> seen;
  for (const auto& c : categorical_palette()) {
    seen.insert({c.r, c.g, c.b});
    // Relative luminance below 0.6 keeps a 2.6 px line visible against white (contrast above 1.6).
    EXPECT_LT(relative_luminance(c), 0.6) << c.r << "," << c.g << "," << c.b;
  }
  EXPECT_EQ(seen.size(), categorical_palette().size());
}

}  // namespace
}  // namespace nibrig::ui::report
