// The row of a spectrum nearest a speed (the Fig. 14 plot compares at the nearest measured speed).
#include "model/io/velocity_spectrum.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace nibrig::model::io {
namespace {

TEST(VelocitySpectrum, NearestSpeedRowPicksTheClosestAndTheFirstOfATie) {
  VelocitySpectrum s;
  s.speeds_m_s = {0.017, 0.05, 0.11, 0.25};
  EXPECT_EQ(nearest_speed_row(s, 0.0), 0u);
  EXPECT_EQ(nearest_speed_row(s, 0.06), 1u);
  EXPECT_EQ(nearest_speed_row(s, 0.2), 3u);
  VelocitySpectrum tie;
  tie.speeds_m_s = {0.25, 0.5, 0.75};
  EXPECT_EQ(nearest_speed_row(tie, 0.625), 1u);  // 0.125 from 0.5 and from 0.75, exactly: the first
  EXPECT_EQ(nearest_speed_row(s, 1.0), 3u);
  EXPECT_EQ(nearest_speed_row(VelocitySpectrum{}, 0.1), 0u);
}

TEST(VelocitySpectrum, AtOtherFrequenciesEachRowIsInterpolatedBetweenItsNearestBins) {
  // A 48 kHz rig session's 2/3 Hz bins put on the bundled catalog's 2 Hz grid: a line in frequency
  // per row is reproduced exactly (to rounding) by linear interpolation.
  VelocitySpectrum fine;
  fine.speeds_m_s = {0.017, 0.25};
  for (int k = 9; k <= 749; ++k) fine.frequencies_hz.push_back(k * 2.0 / 3.0);
  for (double slope : {1e-4, -2e-5}) {
    std::vector<double> row;
    for (double f : fine.frequencies_hz) row.push_back(0.05 + slope * f);
    fine.amplitude_m_s2.push_back(row);
  }
  const std::vector<double> grid = {6.0, 8.0, 250.0, 498.0, 499.0};
  const VelocitySpectrum coarse = spectrum_at_frequencies(fine, grid);
  EXPECT_EQ(coarse.frequencies_hz, grid);
  EXPECT_EQ(coarse.speeds_m_s, fine.speeds_m_s);
  for (std::size_t k = 0; k < grid.size(); ++k) {
    EXPECT_NEAR(coarse.amplitude_m_s2[0][k], 0.05 + 1e-4 * grid[k], 1e-15);
    EXPECT_NEAR(coarse.amplitude_m_s2[1][k], 0.05 - 2e-5 * grid[k], 1e-15);
  }
  // A frequency the spectrum does not reach is refused, naming it and the range.
  try {
    spectrum_at_frequencies(fine, std::vector<double>{4.0});
    FAIL() << "4 Hz lies below the spectrum";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("frequency 4 Hz"), std::string::npos) << e.what();
  }
  EXPECT_THROW(spectrum_at_frequencies(VelocitySpectrum{{6.0}, {0.1}, {{1.0}}}, grid),
               std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::model::io
