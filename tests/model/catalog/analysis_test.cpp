#include "model/catalog/analysis.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "model/io/format_error.hpp"
#include "model/io/rig_session.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::catalog {
namespace {

// A synthetic rig session with known physics: the tip speed ramps 20 -> 240 mm/s, the accelerometer
// sees a 100 Hz sinusoid whose amplitude is 10 s^-1 x speed (stored in raw units at 0.5 m/s^2 per
// unit, so the calibration must be applied), and after 2 s the tangential force is 0.25 x the 2 N
// load.
io::RigSession write_and_read_synthetic_session(const std::filesystem::path& folder, float normal_force_N = 2.0f) {
  io::RigSessionInfo info;
  info.tool = "synthetic";
  info.surface = "bench";
  info.normal_load_N = 2.0;
  info.acceleration_rate_hz = 6400.0;
  info.speed_rate_hz = 100.0;
  info.force_rate_hz = 1000.0;
  info.calibration.accelerometer_m_s2_per_unit = 0.5;
  const double duration_s = 20.0;
  auto speed_at = [&](double t) { return 0.020 + (0.240 - 0.020) * t / duration_s; };

  io::RigSessionWriter writer(folder, info);
  std::vector<float> block;
  for (int i = 0; i < static_cast<int>(duration_s * info.acceleration_rate_hz); ++i) {
    const double t = i / info.acceleration_rate_hz;
    const double a = 10.0 * speed_at(t) * std::sin(2.0 * std::numbers::pi * 100.0 * t);
    block.push_back(static_cast<float>(a / info.calibration.accelerometer_m_s2_per_unit));
  }
  writer.append_acceleration(block);
  block.clear();
  for (int i = 0; i < static_cast<int>(duration_s * info.speed_rate_hz); ++i) {
    block.push_back(static_cast<float>(speed_at(i / info.speed_rate_hz)));
  }
  writer.append_speed(block);
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.01);
  std::vector<float> normal, tangential;
  for (int i = 0; i < static_cast<int>(duration_s * info.force_rate_hz); ++i) {
    const double t = i / info.force_rate_hz;
    normal.push_back(normal_force_N);
    tangential.push_back(static_cast<float>((t >= 2.0 ? 0.5 : 0.0) + noise(rng)));
  }
  writer.append_normal_force(normal);
  writer.append_tangential_force(tangential);
  writer.finish();
  return io::read_rig_session(folder);
}

TEST(AnalyzeSession, RecoversFrictionAndTheSpeedDependentSpectrum) {
  const auto dir = nibrig::test::scratch_dir("analyze_session");
  const auto session = write_and_read_synthetic_session(dir / "session");
  const auto threshold =
      measure::ThresholdCurve::load(nibrig::test::assets_dir() / "thresholds/israr2006_pen_hold.csv");
  AnalysisOptions options;
  options.binning.smoothing_bins = 1;  // compare the raw peak with the closed form
  const auto analysis = analyze_session(session, threshold, options);

  ASSERT_TRUE(analysis.friction.has_value());
  // Independent white noise of 0.01 N over ~17 s of contact: the interval is a few 1e-4 wide; the
  // estimate must be 0.25 within 0.002 and the interval must cover the truth.
  EXPECT_NEAR(analysis.friction->fit.mu, 0.25, 0.002);
  EXPECT_LE(analysis.friction->fit.mu_ci_low, 0.25);
  EXPECT_GE(analysis.friction->fit.mu_ci_high, 0.25);

  ASSERT_TRUE(analysis.vibration.has_value());
  const auto& spectrum = analysis.vibration->spectrum;
  ASSERT_EQ(spectrum.speeds_m_s.size(), options.session_speed_edges_m_s.size() - 1);
  for (std::size_t s = 0; s < spectrum.speeds_m_s.size(); ++s) {
    const auto& row = spectrum.amplitude_m_s2[s];
    const auto peak = std::max_element(row.begin(), row.end()) - row.begin();
    EXPECT_NEAR(spectrum.frequencies_hz[static_cast<std::size_t>(peak)], 100.0, 1e-9);
    // Amplitude 10 x speed, linear in time, so the mean over a bin is 10 x the bin's mean speed;
    // 2 %: the amplitude changes by up to 1 % within one 80 ms segment.
    EXPECT_NEAR(row[static_cast<std::size_t>(peak)], 10.0 * spectrum.speeds_m_s[s],
                0.02 * 10.0 * spectrum.speeds_m_s[s]);
  }
}

// Issue 46: a load near nothing ("autocorrelation: non-finite sample" once the tangential force was
// divided by it) is named with where it came from and the range μ needs; the vibration is still
// measured.
TEST(AnalyzeSession, ALoadBelowAPenRestingOnPaperIsNamedNotDividedBy) {
  const auto dir = nibrig::test::scratch_dir("analyze_session_no_load");
  const auto session = write_and_read_synthetic_session(dir / "lifted", 0.0f);
  const auto threshold =
      measure::ThresholdCurve::load(nibrig::test::assets_dir() / "thresholds/israr2006_pen_hold.csv");
  const SessionAnalysis a = analyze_session(session, threshold, AnalysisOptions{});
  EXPECT_FALSE(a.friction.has_value());
  EXPECT_TRUE(a.vibration.has_value());
  ASSERT_EQ(a.warnings.size(), 1u);
  EXPECT_EQ(a.warnings[0],
            "friction not measured: the normal load is 0 N (the mean of normal_force), expected 0.01 to 50 N to "
            "divide the tangential force by");
}

TEST(AnalyzeSession, ReadsASessionCutShortAndSaysSo) {
  const auto dir = nibrig::test::scratch_dir("analyze_partial");
  io::RigSessionInfo info;
  info.tool = "t";
  info.surface = "s";
  info.normal_load_N = 2.2;
  info.acceleration_rate_hz = 1000.0;
  info.speed_rate_hz = 100.0;
  info.force_rate_hz = 1000.0;
  {
    io::RigSessionWriter writer(dir / "cut", info);
    std::vector<float> force(10000);
    for (std::size_t i = 0; i < force.size(); ++i) force[i] = i < 2000 ? 0.0f : 0.44f;
    writer.append_tangential_force(force);
    // No finish(): the capture was interrupted.
  }
  const auto session = io::read_rig_session(io::partial_folder_of(dir / "cut"));
  EXPECT_FALSE(session.complete);
  const auto threshold =
      measure::ThresholdCurve::load(nibrig::test::assets_dir() / "thresholds/israr2006_pen_hold.csv");
  const AnalysisOptions options;
  const auto analysis = analyze_session(session, threshold, options);
  EXPECT_FALSE(analysis.complete);
  ASSERT_TRUE(analysis.friction.has_value());
  // No normal-force stream was recorded, so the nominal 2.2 N load is used: μ = 0.44 / 2.2.
  EXPECT_NEAR(analysis.friction->fit.mu, 0.2, 1e-6);
}

// A recording that reads but is too short to measure names its file, not only the step
// segmentation's "256 samples cannot hold ...".
TEST(Analysis, ARecordingTooShortToMeasureNamesItsFile) {
  io::VibrationRecording recording;
  recording.source = "piovarci2018/vibration/arm2/arm_cut_short.csv";
  recording.name.tool = "cut";
  recording.name.surface = "short";
  recording.sample_rate_hz = 1000.0;
  recording.acceleration_m_s2.assign(256, 0.1);
  for (std::size_t i = 0; i < 256; ++i) recording.time_s.push_back(static_cast<double>(i) / 1000.0);
  const auto threshold =
      measure::ThresholdCurve::load(nibrig::test::assets_dir() / "thresholds/israr2006_pen_hold.csv");
  try {
    analyze_vibration(recording, threshold, AnalysisOptions{});
    FAIL() << "a quarter second was measured as a sweep";
  } catch (const io::FormatError& e) {
    EXPECT_EQ(e.file(), recording.source);
    EXPECT_NE(std::string(e.what()).find("too short for the step protocol"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace nibrig::model::catalog
