#include "rig/replay_rig.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "model/catalog/analysis.hpp"
#include "model/catalog/compact.hpp"
#include "model/design/tool_sound.hpp"
#include "model/io/bundled_assets.hpp"
#include "model/io/catalog_file.hpp"
#include "model/io/paper_friction.hpp"
#include "model/measure/threshold_curve.hpp"
#include "rig/capture.hpp"
#include "rig/simulated_rig.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::rig {
namespace {

model::catalog::SessionAnalysis measure_session(const std::filesystem::path& folder) {
  const auto threshold = model::measure::ThresholdCurve::load(model::io::default_threshold_curve());
  const model::catalog::AnalysisOptions options;
  return model::catalog::analyze_session(model::io::read_rig_session(folder), threshold, options);
}

// The acceptance check of the replay rig and of the whole capture-and-measure chain: the paper's
// recording of vero2 on office, replayed as if live, captured into a session and measured as any
// session, gives the bundled catalog's spectrum of that pairing within 0.1 dB at every bin. What
// may differ: the session stores float32 samples, and the catalog is bundled on a 2 Hz grid with 4
// significant digits (about 0.001 dB).
TEST(ReplayRig, PaperRecordingReplayedAndMeasuredGivesTheCatalogSpectrum) {
  const auto recording =
      nibrig::test::shared_data() / "piovarci2018/vibration/prints/arm_plain_vero_2_office.csv.gz";
  ReplayRig rig(recording, 0.0);
  EXPECT_EQ(rig.description().tool, "vero2");
  EXPECT_EQ(rig.description().surface, "office");
  const auto dir = nibrig::test::scratch_dir("replay_paper_recording");
  CaptureOptions options;
  options.folder = dir / "vero2_office";
  const CaptureResult result = capture_session(rig, rig.recorded_profile(), options);
  EXPECT_TRUE(result.complete);

  const auto analysis = measure_session(result.folder);
  ASSERT_TRUE(analysis.vibration.has_value());
  EXPECT_EQ(analysis.vibration->steps.size(), 18u);  // 3 sweeps of 6 steps, from the profile
  const auto catalog = model::io::read_catalog(model::io::default_catalog());
  const auto& expected = model::design::pairing_spectrum(catalog, {}, "vero2", "office");
  const double step = expected.frequencies_hz[1] - expected.frequencies_hz[0];
  const auto got = model::catalog::resample_spectrum(analysis.vibration->spectrum, step);
  ASSERT_TRUE(model::io::same_grid(got, expected));
  double worst_db = 0.0;
  for (std::size_t m = 0; m < got.speeds_m_s.size(); ++m)
    for (std::size_t f = 0; f < got.frequencies_hz.size(); ++f)
      worst_db = std::max(worst_db, std::abs(20.0 * std::log10(got.amplitude_m_s2[m][f] /
                                                               expected.amplitude_m_s2[m][f])));
  RecordProperty("worst_db", std::to_string(worst_db));
  EXPECT_LT(worst_db, 0.1);
}

// A captured session replayed and captured again is the same session, sample for sample.
TEST(ReplayRig, SessionReplayedIsCapturedUnchanged) {
  const auto dir = nibrig::test::scratch_dir("replay_session");
  model::design::ToolSounds sounds({});
  SimulatedRigSettings settings;
  settings.speedup = 0.0;
  SimulatedRig simulated(settings, sounds.sound("vero2", "office"), "vero2", "office");
  CaptureOptions first;
  first.folder = dir / "original";
  capture_session(simulated, study_sweep_profile(2.0), first);

  ReplayRig replay(dir / "original", 0.0);
  EXPECT_EQ(replay.recorded_profile().description(), study_sweep_profile(2.0).description());
  CaptureOptions second;
  second.folder = dir / "replayed";
  const CaptureResult result = capture_session(replay, replay.recorded_profile(), second);
  EXPECT_TRUE(result.complete);
  const auto a = model::io::read_rig_session(dir / "original");
  const auto b = model::io::read_rig_session(dir / "replayed");
  EXPECT_EQ(a.acceleration, b.acceleration);
  EXPECT_EQ(a.speed_m_s, b.speed_m_s);
  EXPECT_EQ(a.normal_force_N, b.normal_force_N);
  EXPECT_EQ(a.tangential_force_N, b.tangential_force_N);
  EXPECT_EQ(a.info.calibration.accelerometer_m_s2_per_unit,
            b.info.calibration.accelerometer_m_s2_per_unit);
  EXPECT_EQ(a.info.profile_time_s, b.info.profile_time_s);
}

// The paper measured vibration and friction in separate runs: vero2 on glass replayed with its
// friction run beside it gives a session whose μ is the one the catalog analysis finds in that run.
// The replay holds the force samples on the accelerometer's frame clock (the two ~1 kHz rates
// differ by up to 0.1 %), which moves μ by about 0.1 %, far less than the force's own wander that
// sets the 95 % interval: a fifth of its half-width is allowed.
TEST(ReplayRig, APaperRecordingReplayedWithItsFrictionRunMeasuresTheCatalogsMu) {
  const auto data = nibrig::test::shared_data() / "piovarci2018";
  const auto vibration = data / "vibration/arm2/glass/arm_vero_2_glass.csv.gz";
  const auto friction = data / "friction/printed/vero2_glass_2.2N_13.7_1.csv.gz";
  ReplayRig rig(vibration, 0.0, friction);
  EXPECT_DOUBLE_EQ(rig.description().normal_load_N, 2.2);
  const auto dir = nibrig::test::scratch_dir("replay_with_friction");
  CaptureOptions options;
  options.folder = dir / "vero2_glass";
  ASSERT_TRUE(capture_session(rig, rig.recorded_profile(), options).complete);
  const auto analysis = measure_session(options.folder);
  ASSERT_TRUE(analysis.friction.has_value());
  ASSERT_TRUE(analysis.vibration.has_value());
  const auto expected =
      model::catalog::analyze_friction(model::io::read_paper_friction(friction), {});
  const double half_width = (expected.fit.mu_ci_high - expected.fit.mu_ci_low) / 2;
  RecordProperty("mu", std::to_string(analysis.friction->fit.mu));
  RecordProperty("paper_mu", std::to_string(expected.fit.mu));
  EXPECT_NEAR(analysis.friction->fit.mu, expected.fit.mu, half_width / 5);
}

TEST(ReplayRig, ClearErrorsForWhatCannotBeReplayed) {
  EXPECT_THROW(ReplayRig("/nonexistent/session", 1.0), std::invalid_argument);
  const auto dir = nibrig::test::scratch_dir("replay_errors");
  EXPECT_THROW(ReplayRig(dir, 1.0), std::exception);  // a folder without session.json
  const auto data = nibrig::test::shared_data() / "piovarci2018";
  // A friction run on another surface than the vibration's.
  EXPECT_THROW(ReplayRig(data / "vibration/arm2/glass/arm_vero_2_glass.csv.gz", 0.0,
                         data / "friction/printed/vero2_note_2.2N_13.7_1.csv.gz"),
               std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::rig
