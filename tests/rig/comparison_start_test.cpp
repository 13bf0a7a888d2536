// The rig comparison as every face starts it, reached without a face: each refusal names the field
// of the request at fault, before anything opens where it can; and a comparison through the request
// is the comparison run by hand on the same rig, with the report made from its table.
#include "rig/comparison_start.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "model/io/bundled_assets.hpp"
#include "model/measure/threshold_curve.hpp"
#include "rig/simulated_rig.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::rig {
namespace {

using Field = RigRequestRefused::Field;

ComparisonRequest simulated_vero2(const std::filesystem::path& session) {
  ComparisonRequest r;
  r.rig.tool = "vero2", r.rig.surface = "office", r.rig.speedup = 0.0, r.rig.seed = 11;
  r.seconds = 6.0;
  r.session = session;
  r.seed = 12;
  return r;
}

// The field a request is refused for, at construction or when it opens.
std::optional<Field> refused_field(ComparisonRequest r, bool open = false) {
  try {
    ComparisonStart start(std::move(r));
    if (open) start.open();
  } catch (const RigRequestRefused& e) {
    return e.field();
  }
  return std::nullopt;
}

TEST(ComparisonStart, EachRefusalNamesTheFieldAtFault) {
  const auto dir = nibrig::test::scratch_dir("comparison_start_refused");
  const ComparisonRequest ok = simulated_vero2(dir / "s");
  EXPECT_EQ(refused_field(ok), std::nullopt);

  auto r = ok;
  r.rig.tool.clear();
  EXPECT_EQ(refused_field(r), Field::tool);
  r = ok, r.rig.surface.clear();
  EXPECT_EQ(refused_field(r), Field::surface);
  r = ok, r.rig.load_N = 1e308;
  EXPECT_EQ(refused_field(r), Field::load);
  r = ok, r.rig.speedup = -1.0;
  EXPECT_EQ(refused_field(r), Field::speedup);
  r = ok, r.seconds = 1e-320;
  EXPECT_EQ(refused_field(r), Field::seconds);
  r = ok, r.profile = (dir / "no-such-profile.csv").string();
  EXPECT_EQ(refused_field(r), Field::profile);

  r = ok, r.rig.kind = RigKind::replay;
  EXPECT_EQ(refused_field(r), Field::replay);
  r.rig.replay =
      nibrig::test::shared_data() / "piovarci2018/vibration/prints/arm_plain_vero_2_office.csv.gz";
  r.profile = "steps";
  EXPECT_EQ(refused_field(r), Field::profile);  // a replay runs what it recorded

  r = ok, r.rig.kind = RigKind::usb, r.rig.input_channel = 0;
  EXPECT_EQ(refused_field(r), Field::input_channel);
  r.rig.input_channel = 4096;  // a typo: no interface has that many inputs
  EXPECT_EQ(refused_field(r), Field::input_channel);
  r = ok, r.rig.kind = RigKind::usb, r.rig.accelerometer_m_s2_per_full_scale = 0.0;
  EXPECT_EQ(refused_field(r), Field::accelerometer);

  // Known only once the catalog is read: a tool it lacks, mounted or simulated.
  r = ok, r.rig.tool = "no-such-tool";
  EXPECT_EQ(refused_field(r, true), Field::tool);
  r = ok, r.simulate = "no-such-tool";
  EXPECT_EQ(refused_field(r, true), Field::simulate);
  EXPECT_FALSE(std::filesystem::exists(dir / "s"));  // nothing ran
}

// The same rig (a simulated rig is deterministic for its seed) and the same simulation seed give
// the same table whether the face runs the request or the comparison by hand; 0.05 dB allows only
// for how the capture's batches meet the analysis thread, far below the 1.5-2 dB the comparison of
// a tool with itself leaves (comparison_run_test.cpp).
TEST(ComparisonStart, RunsTheComparisonAsByHandAndReportsItsTable) {
  const auto dir = nibrig::test::scratch_dir("comparison_start_run");
  const RigComparison through = compare_on_rig(simulated_vero2(dir / "request"));

  model::design::ToolSounds sounds({});
  SimulatedRigSettings settings;
  settings.speedup = 0.0, settings.seed = 11;
  SimulatedRig rig(settings, sounds.sound("vero2", "office"), "vero2", "office");
  ComparisonRunOptions options;
  options.capture.folder = dir / "by-hand";
  options.seed = 12;
  const auto threshold = model::measure::ThresholdCurve::load(model::io::default_threshold_curve());
  const ComparisonRun by_hand = run_comparison(rig, study_sweep_profile(6.0),
                                               sounds.sound("vero2", "office"), threshold, options);

  EXPECT_TRUE(through.run.capture.complete);
  EXPECT_EQ(through.run.capture.folder, dir / "request");
  EXPECT_NEAR(through.run.table.summary.mean_lsd_db, by_hand.table.summary.mean_lsd_db, 0.05);
  EXPECT_EQ(through.run.table.summary.bins_with_rows, by_hand.table.summary.bins_with_rows);
  EXPECT_EQ(through.report.tool, "vero2");
  EXPECT_EQ(through.report.surface, "office");
  EXPECT_DOUBLE_EQ(through.report.mean_lsd_db, through.run.table.summary.mean_lsd_db);
  EXPECT_EQ(through.simulated_modes, sounds.sound("vero2", "office").modes);
}

}  // namespace
}  // namespace nibrig::rig
