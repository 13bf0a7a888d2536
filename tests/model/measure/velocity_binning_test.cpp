#include "model/measure/velocity_binning.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tests/model/measure/gz_csv.hpp"
#include "tests/model/measure/reference_dft.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::measure {
namespace {

TEST(SmoothShrinkingSpan, AveragesFiveBinsAndShrinksAtTheEnds) {
  const std::vector<double> x{1, 2, 4, 8, 16, 32, 64};
  const auto y = smooth_shrinking_span(x, 5);
  // MATLAB smooth(x, 5): spans 1, 3, 5, 5, 5, 3, 1 (written out by hand).
  const std::vector<double> expected{1, 7.0 / 3, 31.0 / 5, 62.0 / 5, 124.0 / 5, 112.0 / 3, 64};
  ASSERT_EQ(y.size(), expected.size());
  for (std::size_t i = 0; i < y.size(); ++i) EXPECT_DOUBLE_EQ(y[i], expected[i]);
  EXPECT_EQ(smooth_shrinking_span(x, 1), x);
  EXPECT_EQ(smooth_shrinking_span(x, 6), y);  // even spans lose one, as in MATLAB
  EXPECT_THROW(smooth_shrinking_span(x, 0), std::invalid_argument);
}

// The paper's AverageReadings3 on one file, written out independently: 1-based rows → 0-based, a
// direct DFT, |Y|·2/N for MATLAB bins 10..750, mean over the 3 columns of reshape(…, 14000, 3),
// smooth.
std::vector<std::vector<double>> paper_spectra(const std::vector<double>& d,
                                               std::size_t first_row) {
  const std::size_t s0 = first_row - 1;
  std::vector<std::vector<double>> rows;
  for (std::size_t i = 2000; i <= 12000;
       i += 2000) {  // MATLAB: for i = 2000:2000:N-2000, N = 14000
    std::vector<double> my(741, 0.0);
    for (std::size_t j = 0; j < 3; ++j) {
      // y = ds(i+250 : i+1749, j): 1-based within the column → 0-based offset i + 249.
      const std::size_t begin = s0 + 14000 * j + i + 249;
      std::vector<double> y(d.begin() + static_cast<std::ptrdiff_t>(begin),
                            d.begin() + static_cast<std::ptrdiff_t>(begin + 1500));
      double mean = 0.0;
      for (double v : y) mean += v / 1500.0;
      for (double& v : y) v -= mean;
      const auto Y = nibrig::test::direct_dft(y);
      for (std::size_t k = 9; k <= 749; ++k) my[k - 9] += std::abs(Y[k]) * 2.0 / 1500.0 / 3.0;
    }
    std::vector<double> smoothed(741);
    for (std::size_t b = 0; b < 741; ++b) {
      const std::size_t h = std::min<std::size_t>({2, b, 740 - b});
      double s = 0.0;
      for (std::size_t q = b - h; q <= b + h; ++q) s += my[q];
      smoothed[b] = s / static_cast<double>(2 * h + 1);
    }
    rows.push_back(smoothed);
  }
  return rows;
}

TEST(SpectrumPerStep, ReproducesThePapersSpectraOnItsOwnWindows) {
  const auto path =
      nibrig::test::shared_data() / "piovarci2018/vibration/prints/arm_plain_vero_1_office.csv.gz";
  auto column = nibrig::test::read_gz_csv_column(path, 2);
  std::vector<double> x = column.values;
  for (double& v : x) v *= 9.80665;  // g → m/s²
  // The paper's windows for this file (start row 4), handed over as a segmentation.
  StepSegmentation seg;
  const auto speeds = default_step_speeds_m_s();
  for (std::size_t j = 0; j < 3; ++j) {
    for (std::size_t k = 1; k <= 6; ++k) {
      const std::size_t begin = 3 + 14000 * j + 2000 * k + 249;
      seg.steps.push_back({begin, begin + 1500, j, k, speeds[k - 1], 0.0});
    }
  }
  const io::VelocitySpectrum ours = spectrum_per_step(x, 1000.0, seg, BinningSettings{});
  const auto reference = paper_spectra(x, 4);
  ASSERT_EQ(ours.frequencies_hz.size(), 741u);  // the paper's 741 bins
  EXPECT_NEAR(ours.frequencies_hz.front(), 6.0, 1e-12);
  EXPECT_NEAR(ours.frequencies_hz.back(), 749.0 / 1.5, 1e-9);
  ASSERT_EQ(ours.speeds_m_s, speeds);
  for (std::size_t r = 0; r < 6; ++r) {
    for (std::size_t b = 0; b < 741; ++b) {
      // FFT vs direct DFT of the same samples: rounding only (values ~1e-3..1e-1 m/s²).
      ASSERT_NEAR(ours.amplitude_m_s2[r][b], reference[r][b], 1e-11)
          << "speed " << r << " bin " << b;
    }
  }
}

TEST(SpectrumPerStep, RejectsUnequalWindows) {
  std::vector<double> x(10000, 0.0);
  StepSegmentation seg;
  seg.steps.push_back({0, 1500, 0, 1, 0.1, 0.0});
  seg.steps.push_back({2000, 3000, 0, 2, 0.2, 0.0});
  EXPECT_THROW(spectrum_per_step(x, 1000.0, seg, BinningSettings{}), std::invalid_argument);
  seg.steps.pop_back();
  seg.steps.push_back({9000, 10500, 0, 2, 0.2, 0.0});  // past the end
  EXPECT_THROW(spectrum_per_step(x, 1000.0, seg, BinningSettings{}), std::invalid_argument);
  EXPECT_THROW(spectrum_per_step(x, 1000.0, StepSegmentation{}, BinningSettings{}),
               std::invalid_argument);
}

// A synthetic rig recording: the speed holds 4 levels for 5 s each; the acceleration is a sinusoid
// whose frequency and amplitude are known functions of speed, f(v) = 40 Hz + 2000 v,
// A(v) = 0.2 + 4 v (m/s²), put on bin centres of 1024-sample segments at 2048 Hz (2 Hz bins).
TEST(SpectrumBySpeed, PutsEachSpeedsSinusoidInItsBinAtItsAmplitude) {
  const double fs = 2048.0, speed_rate = 100.0;
  const std::vector<double> levels{0.05, 0.10, 0.15, 0.20};
  auto freq = [](double v) { return 40.0 + 2000.0 * v; };  // 140, 240, 340, 440 Hz: bins 70..220
  auto amp = [](double v) { return 0.2 + 4.0 * v; };
  const std::size_t per_level = 5 * 2048;
  std::vector<double> acc(levels.size() * per_level);
  for (std::size_t i = 0; i < acc.size(); ++i) {
    const double v = levels[i / per_level];
    acc[i] = amp(v) * std::sin(2.0 * std::numbers::pi * freq(v) * static_cast<double>(i) / fs);
  }
  std::vector<double> speed(static_cast<std::size_t>(20.0 * speed_rate) + 1);
  for (std::size_t i = 0; i < speed.size(); ++i) {
    speed[i] = levels[std::min<std::size_t>(i / 500, levels.size() - 1)];
  }
  const std::vector<double> edges{0.025, 0.075, 0.125, 0.175, 0.225, 0.30};
  BinningSettings binning;
  binning.min_frequency_hz = 100.0;
  binning.max_frequency_hz = 500.0;
  binning.smoothing_bins = 1;
  SpeedBinningReport report;
  const io::VelocitySpectrum vs =
      spectrum_by_speed(acc, fs, speed, speed_rate, edges, SpectrogramSettings{}, binning, &report);

  ASSERT_EQ(vs.speeds_m_s.size(), 4u);  // the fifth bin (0.225-0.30) is empty and dropped
  ASSERT_EQ(report.empty_bins, std::vector<std::size_t>{4});
  EXPECT_EQ(report.segments_outside_speed_record, 0u);
  EXPECT_NEAR(vs.frequencies_hz.front(), 100.0, 1e-12);
  EXPECT_LT(vs.frequencies_hz.back(), 500.0);
  for (std::size_t b = 0; b < 4; ++b) {
    const double v = levels[b];
    // Speeds in a bin are those of its level except for segment centres inside a 10 ms
    // interpolation ramp between two speed samples: the mean stays within 1 % of the level.
    EXPECT_NEAR(vs.speeds_m_s[b] / v, 1.0, 0.01) << "bin " << b;
    const auto k = static_cast<std::size_t>(std::lround((freq(v) - 100.0) / 2.0));
    ASSERT_NEAR(vs.frequencies_hz[k], freq(v), 1e-9);
    // Of the ~37 segments in a bin, the 3-4 that straddle a speed change hold the tone for part of
    // their length only; a Hann-weighted part of at least half keeps their reading above ~0.5 A.
    // The mean is therefore within 5 % of A(v) (measured: 1-3 %), and far from the other tones.
    EXPECT_NEAR(vs.amplitude_m_s2[b][k] / amp(v), 1.0, 0.05) << "bin " << b;
    for (std::size_t other = 0; other < 4; ++other) {
      if (other == b) continue;
      const auto ko = static_cast<std::size_t>(std::lround((freq(levels[other]) - 100.0) / 2.0));
      // Another speed's tone only appears through straddling segments: under 10 % of its amplitude.
      EXPECT_LT(vs.amplitude_m_s2[b][ko], 0.1 * amp(levels[other]))
          << "bin " << b << " tone " << other;
    }
  }
}

TEST(SpectrumBySpeed, RejectsBadEdgesAndRates) {
  std::vector<double> acc(4096, 0.0), speed(100, 0.1);
  const SpectrogramSettings sg;
  const BinningSettings bs;
  const std::vector<double> one{0.1};
  const std::vector<double> down{0.2, 0.1};
  const std::vector<double> ok{0.0, 0.05};  // speeds (0.1) outside every bin
  EXPECT_THROW(spectrum_by_speed(acc, 1000.0, speed, 10.0, one, sg, bs), std::invalid_argument);
  EXPECT_THROW(spectrum_by_speed(acc, 1000.0, speed, 10.0, down, sg, bs), std::invalid_argument);
  EXPECT_THROW(spectrum_by_speed(acc, 0.0, speed, 10.0, ok, sg, bs), std::invalid_argument);
  EXPECT_THROW(spectrum_by_speed(acc, 1000.0, speed, -1.0, ok, sg, bs), std::invalid_argument);
  EXPECT_THROW(spectrum_by_speed(acc, 1000.0, speed, 10.0, ok, sg, bs), std::runtime_error);
}

}  // namespace
}  // namespace nibrig::model::measure
