#include "model/catalog/compact.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace nibrig::model::catalog {
namespace {

TEST(ResampleSpectrum, ReproducesALinearSpectrumExactly) {
  // Linear interpolation is exact for a spectrum linear in frequency: the closed-form reference.
  io::VelocitySpectrum s;
  s.speeds_m_s = {0.05, 0.1};
  for (double f = 6.0; f <= 500.0; f += 2.0 / 3.0) s.frequencies_hz.push_back(f);
  for (double v : s.speeds_m_s) {
    std::vector<double> row;
    for (double f : s.frequencies_hz) row.push_back(v * (1.0 + 0.01 * f));
    s.amplitude_m_s2.push_back(row);
  }
  const auto r = resample_spectrum(s, 2.0);
  ASSERT_EQ(r.speeds_m_s, s.speeds_m_s);
  EXPECT_DOUBLE_EQ(r.frequencies_hz.front(), 6.0);
  EXPECT_LE(r.frequencies_hz.back(), s.frequencies_hz.back());
  for (std::size_t i = 0; i < r.speeds_m_s.size(); ++i) {
    for (std::size_t k = 0; k < r.frequencies_hz.size(); ++k) {
      // 1e-12: only rounding of the interpolation weights.
      EXPECT_NEAR(r.amplitude_m_s2[i][k], r.speeds_m_s[i] * (1.0 + 0.01 * r.frequencies_hz[k]),
                  1e-12);
    }
  }
}

TEST(RoundSignificant, KeepsTheRequestedDigits) {
  EXPECT_DOUBLE_EQ(round_significant(0.00123456, 4), 0.001235);
  EXPECT_DOUBLE_EQ(round_significant(-98765.4, 3), -98800.0);
  EXPECT_DOUBLE_EQ(round_significant(0.0, 4), 0.0);
}

TEST(CompactCatalog, RecordsWhatWasDoneInTheProvenance) {
  io::Catalog c;
  io::Pairing p;
  p.tool = "vero1";
  p.surface = "office";
  p.vibration.emplace();
  p.vibration->spectrum.frequencies_hz = {6.0, 7.0, 8.0, 9.0};
  p.vibration->spectrum.speeds_m_s = {0.017};
  p.vibration->spectrum.amplitude_m_s2 = {{1.234567, 2.345678, 3.456789, 4.567891}};
  c.pairings.push_back(p);
  const auto out = compact_catalog(c, 1.0, 3);
  EXPECT_DOUBLE_EQ(out.pairings[0].vibration->spectrum.amplitude_m_s2[0][1], 2.35);
  EXPECT_NE(out.pairings[0].vibration->provenance.method.find("3 significant digits"),
            std::string::npos);
}

}  // namespace
}  // namespace nibrig::model::catalog
