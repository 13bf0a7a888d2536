#include "model/measure/descriptors.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "tests/support/test_paths.hpp"

namespace nibrig::model::measure {
namespace {

io::VelocitySpectrum flat_spectrum(std::size_t bins, double df, double amplitude) {
  io::VelocitySpectrum s;
  for (std::size_t i = 0; i < bins; ++i)
    s.frequencies_hz.push_back(10.0 + df * static_cast<double>(i));
  s.speeds_m_s = {0.05, 0.1, 0.2};
  s.amplitude_m_s2.assign(3, std::vector<double>(bins, amplitude));
  return s;
}

TEST(VibrationDescriptors, FlatSpectrumOnFlatThresholdHasClosedForms) {
  const ThresholdCurve flat({1.0, 1000.0}, {0.2, 0.2}, "flat");
  const auto s = flat_spectrum(100, 2.0, 0.6);
  const VibrationDescriptors d = compute_vibration_descriptors(s, flat, 5);
  // r = 0.6 / 0.2 = 3 everywhere: mean 3; power = 3² · (100 bins · 2 Hz) = 1800.
  EXPECT_DOUBLE_EQ(d.weighted_mean, 3.0);
  EXPECT_NEAR(d.weighted_power, 1800.0, 1e-9);
  ASSERT_EQ(d.band_energies.size(), 5u);
  for (int k = 1; k <= 5; ++k) {
    const auto& bands = d.band_energies.at(k);
    ASSERT_EQ(bands.size(), static_cast<std::size_t>(k));
    // Flat density over a range split evenly: each band holds 1800 / k.
    for (double e : bands) EXPECT_NEAR(e, 1800.0 / k, 1e-9) << "k " << k;
  }
}

TEST(VibrationDescriptors, BandsAddUpToThePowerAndOneBandIsThePower) {
  const ThresholdCurve curve =
      ThresholdCurve::load(nibrig::test::assets_dir() / "thresholds/israr2006_pen_hold.csv");
  io::VelocitySpectrum s = flat_spectrum(741, 2.0 / 3.0, 0.0);
  for (std::size_t r = 0; r < 3; ++r) {
    for (std::size_t i = 0; i < 741; ++i) {
      s.amplitude_m_s2[r][i] =
          0.01 * (1.0 + static_cast<double>(r)) * (1.0 + std::sin(0.05 * static_cast<double>(i)));
    }
  }
  const VibrationDescriptors d = compute_vibration_descriptors(s, curve, 7);
  EXPECT_NEAR(d.band_energies.at(1)[0], d.weighted_power, 1e-12 * d.weighted_power);
  for (int k = 2; k <= 7; ++k) {
    const auto& b = d.band_energies.at(k);
    // Cells cut by a band edge are split in proportion, so the bands tile the power exactly.
    EXPECT_NEAR(std::accumulate(b.begin(), b.end(), 0.0), d.weighted_power,
                1e-12 * d.weighted_power);
  }
}

TEST(VibrationDescriptors, PowerIsTheMeanOverSpeedsOfTheBinSum) {
  const ThresholdCurve flat({1.0, 1000.0}, {1.0, 1.0}, "flat");
  io::VelocitySpectrum s{{100.0, 110.0, 120.0}, {0.1, 0.2}, {{1.0, 2.0, 3.0}, {0.0, 0.0, 1.0}}};
  const VibrationDescriptors d = compute_vibration_descriptors(s, flat, 2);
  // Speed 1: (1 + 4 + 9)·10 = 140; speed 2: 1·10 = 10; mean 75. Mean ratio: 7/6.
  EXPECT_NEAR(d.weighted_power, 75.0, 1e-12);
  EXPECT_NEAR(d.weighted_mean, 7.0 / 6.0, 1e-15);
  // Range 95-125 Hz, two bands of 15 Hz: [95,110) holds cell 1 and half of cell 2 — densities
  // (mean over speeds of r²) 0.5, 2, 5 → 0.5·10 + 2·5 = 15; the other band 2·5 + 5·10 = 60.
  EXPECT_NEAR(d.band_energies.at(2)[0], 15.0, 1e-12);
  EXPECT_NEAR(d.band_energies.at(2)[1], 60.0, 1e-12);
}

TEST(VibrationDescriptors, RejectsUnusableSpectra) {
  const ThresholdCurve flat({1.0, 1000.0}, {1.0, 1.0}, "flat");
  io::VelocitySpectrum one{{100.0}, {0.1}, {{1.0}}};
  EXPECT_THROW(compute_vibration_descriptors(one, flat), std::invalid_argument);
  io::VelocitySpectrum none{{100.0, 110.0}, {}, {}};
  EXPECT_THROW(compute_vibration_descriptors(none, flat), std::invalid_argument);
  io::VelocitySpectrum ok{{100.0, 110.0}, {0.1}, {{1.0, 1.0}}};
  EXPECT_THROW(compute_vibration_descriptors(ok, flat, 0), std::invalid_argument);
}

// The demo's descriptor stage over a catalog: a pairing with a spectrum gets exactly what
// compute_vibration_descriptors gives for it and the curve's name; one without is left alone; a
// spectrum that cannot be weighed is named by its pairing.
TEST(VibrationDescriptors, WeighingACatalogWeighsEverySpectrumAndNamesTheCurve) {
  const ThresholdCurve flat({1.0, 1000.0}, {0.2, 0.2}, "flat");
  io::Catalog catalog;
  io::Pairing with{"pen", "office", std::nullopt, io::VibrationDescriptor{}};
  with.vibration->spectrum = flat_spectrum(100, 2.0, 0.6);
  with.vibration->weighted_mean = 99.0;  // stale, from another curve
  io::Pairing without{"pen", "stone", io::FrictionDescriptor{}, std::nullopt};
  catalog.pairings = {with, without};

  EXPECT_EQ(weigh_catalog_vibration(catalog, flat, 3), 1u);
  const auto& v = *catalog.pairings[0].vibration;
  const VibrationDescriptors expected = compute_vibration_descriptors(v.spectrum, flat, 3);
  EXPECT_EQ(v.weighted_mean, expected.weighted_mean);  // 3: the closed form of the test above
  EXPECT_EQ(v.weighted_power, expected.weighted_power);
  EXPECT_EQ(v.band_energies, expected.band_energies);
  EXPECT_EQ(v.threshold_curve, "flat");
  EXPECT_FALSE(catalog.pairings[1].vibration.has_value());

  catalog.pairings[0].vibration->spectrum.amplitude_m_s2.clear();
  try {
    weigh_catalog_vibration(catalog, flat, 3);
    FAIL() << "a spectrum without speeds was weighed";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("pen/office"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace nibrig::model::measure
