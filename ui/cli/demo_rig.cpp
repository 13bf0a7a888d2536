#include "ui/cli/demo_rig.hpp"

#include <cmath>
#include <cstdio>

#include "model/catalog/analysis.hpp"
#include "model/catalog/compact.hpp"
#include "model/design/tool_sound.hpp"
#include "model/forcing/leave_one_out.hpp"
#include "model/io/bundled_assets.hpp"
#include "model/io/comparison_file.hpp"
#include "model/io/rig_session.hpp"
#include "model/measure/threshold_curve.hpp"
#include "rig/comparison_report.hpp"
#include "rig/comparison_run.hpp"
#include "rig/simulated_rig.hpp"
#include "ui/cli/forcing_options.hpp"
#include "ui/cli/output.hpp"
#include "ui/cli/rig_figures.hpp"

namespace nibrig::ui::cli {
namespace {

constexpr const char* kTool = "vero2";
constexpr const char* kSurface = "office";

rig::SimulatedRigSettings fast_rig() {
  rig::SimulatedRigSettings settings;
  settings.speedup = 0.0;  // the demo has no turntable to wait for
  return settings;
}

}  // namespace

DemoSection run_rig_demo(const std::filesystem::path& catalog_file, const std::filesystem::path& report) {
  const auto folder = report / "rig";
  ensure_folder(folder);
  std::filesystem::remove_all(folder / "steps");  // a demo run again replaces its own output
  std::filesystem::remove_all(folder / "compare");
  model::design::ToolSounds sounds({catalog_file, {}, {}, design_progress()});
  const model::design::ToolSound sound = sounds.sound(kTool, kSurface);
  const auto threshold = model::measure::ThresholdCurve::load(model::io::default_threshold_curve());

  // 1. The paper's protocol on the simulated rig, measured as any session, against the catalog.
  rig::SimulatedRig stepped(fast_rig(), sound, kTool, kSurface);
  rig::CaptureOptions capture;
  capture.folder = folder / "steps";
  const rig::CaptureResult captured = rig::capture_session(stepped, rig::paper_steps(42.0), capture);
  const model::catalog::AnalysisOptions analysis_options;
  const auto analysis = model::catalog::analyze_session(model::io::read_rig_session(captured.folder),
                                                        threshold, analysis_options);
  const auto& expected = model::design::pairing_spectrum(sounds.catalog(), catalog_file, kTool, kSurface);
  const double step = expected.frequencies_hz[1] - expected.frequencies_hz[0];
  const auto measured = model::catalog::resample_spectrum(analysis.vibration->spectrum, step);
  const double rms_db = model::forcing::log_spectrum_error(measured, expected).rms_db;

  // 2. The live comparison over the study's sweep.
  rig::SimulatedRig swept(fast_rig(), sound, kTool, kSurface);
  rig::ComparisonRunOptions options;
  ensure_folder(folder / "compare");
  options.capture.folder = folder / "compare" / "session";
  const rig::ComparisonRun run =
      rig::run_comparison(swept, rig::study_sweep_profile(6.0), sound, threshold, options);
  model::io::write_comparison_file(rig::comparison_report(kTool, kSurface, run.table, run.settings),
                                   folder / "compare" / "comparison.json");
  write_comparison_figure(run, std::string(kTool) + " on " + kSurface + " (simulated rig) against " + run.simulated,
                          folder / "compare" / "comparison.png");

  const double weighted_mean_difference =
      std::pow(10.0, run.table.summary.mean_weighted_mean_log10_difference) - 1.0;
  DemoSection section;
  section.numbers = {{"tool", kTool},
                     {"surface", kSurface},
                     {"steps_session_complete", model::io::read_rig_session(captured.folder).complete},
                     {"steps_rms_db_from_catalog", rms_db},
                     {"comparison_mean_distance_db", run.table.summary.mean_lsd_db},
                     {"comparison_speed_bins", run.table.summary.bins_with_rows},
                     {"comparison_weighted_mean_difference", weighted_mean_difference},
                     {"comparison_blocks_dropped", run.table.blocks_dropped}};
  char text[512];
  std::snprintf(text, sizeof text,
                "rig (simulated turntable, %s on %s):\n"
                "  paper steps, 3 sweeps (42 s), captured and measured as a session: %.2f dB RMS from "
                "the catalog spectrum\n"
                "  live comparison over the study's sweep (6 s): mean distance %.2f dB over %zu speed "
                "bins, weighted mean %+.1f %%, %llu blocks dropped\n"
                "  report: %s/ (steps/, compare/comparison.json, compare/comparison.png)\n",
                kTool, kSurface, rms_db, run.table.summary.mean_lsd_db,
                run.table.summary.bins_with_rows,
                100.0 * weighted_mean_difference,
                static_cast<unsigned long long>(run.table.blocks_dropped), folder.string().c_str());
  section.text = text;
  return section;
}

}  // namespace nibrig::ui::cli
