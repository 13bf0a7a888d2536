// `nibrig measure <recording>`: one recording -> its descriptors as JSON, and PNG figures.
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <fstream>
#include <iostream>
#include <stdexcept>

#include "model/catalog/catalog_builder.hpp"
#include "model/io/bundled_assets.hpp"
#include "model/io/paper_recording.hpp"
#include "model/io/rig_session.hpp"
#include "rt/reference_load.hpp"
#include "ui/cli/commands.hpp"
#include "ui/cli/logging.hpp"
#include "ui/cli/measurement_figures.hpp"
#include "ui/cli/output.hpp"
#include "ui/options/number_checks.hpp"

namespace nibrig::ui::cli {

namespace {

struct MeasureOptions {
  std::filesystem::path recording;
  std::filesystem::path output;
  std::filesystem::path plots;
  bool no_plots = false;
  std::filesystem::path threshold;
  // Replace what the file name would say (a recording named anything); the kind, when not given,
  // comes from the name or else from the file's header.
  model::io::StatedRecording stated;
  std::string kind;  // "accelerometer", "friction" or empty
};

model::catalog::RecordingKind kind_of(const MeasureOptions& o) {
  using model::catalog::RecordingKind;
  if (o.kind == "accelerometer") return RecordingKind::paper_vibration;
  if (o.kind == "friction") return RecordingKind::paper_friction;
  return model::catalog::classify_recording_by_content(o.recording);
}

void write_vibration_figures(const model::catalog::VibrationAnalysis& a,
                             const std::filesystem::path& dir, const std::string& stem) {
  const std::string pair = a.tool + " on " + a.surface;
  plot_velocity_spectrum(a.spectrum, "Velocity-binned spectrum: " + pair,
                         dir / (stem + "_velocity_spectrum.png"));
  plot_spectra_by_speed(a.spectrum, "Spectra per speed: " + pair, dir / (stem + "_spectra.png"));
  plot_spectrogram(a.spectrogram, "Spectrogram of the recording: " + pair,
                   dir / (stem + "_spectrogram.png"));
}

void write_friction_figures(const model::catalog::FrictionAnalysis& a,
                            const std::filesystem::path& dir, const std::string& stem) {
  plot_friction_trace(a, dir / (stem + "_friction_trace.png"));
  plot_mu_by_speed(a, dir / (stem + "_mu_by_speed.png"));
}

void measure(const MeasureOptions& options) {
  namespace catalog = model::catalog;
  const auto threshold = model::measure::ThresholdCurve::load(
      options.threshold.empty() ? model::io::default_threshold_curve() : options.threshold);
  const catalog::AnalysisOptions analysis_options;
  const std::string stem = recording_stem(options.recording);
  const std::filesystem::path plot_dir =
      options.plots.empty()
          ? (options.output.empty() ? std::filesystem::path(".") : options.output.parent_path())
          : options.plots;
  nlohmann::json result;
  const auto kind = kind_of(options);
  const auto& stated = options.stated;
  if (kind == catalog::RecordingKind::session &&
      (stated.tool || stated.surface || stated.normal_load_N || stated.lever_factor))
    throw std::invalid_argument(options.recording.string() +
                                ": a rig session names its own tool, surface and load; --tool, "
                                "--surface, --load and --lever are for single CSV recordings");
  switch (kind) {
    case catalog::RecordingKind::paper_friction: {
      const auto a = catalog::analyze_friction(
          model::io::read_paper_friction(options.recording, stated), analysis_options);
      result = catalog::to_json(a);
      if (!options.no_plots) {
        ensure_folder(plot_dir);
        write_friction_figures(a, plot_dir, stem);
      }
      break;
    }
    case catalog::RecordingKind::paper_vibration: {
      const auto a = catalog::analyze_vibration(
          model::io::read_paper_vibration(options.recording, stated), threshold,
          analysis_options);
      result = catalog::to_json(a, threshold);
      if (!options.no_plots) {
        ensure_folder(plot_dir);
        write_vibration_figures(a, plot_dir, stem);
      }
      break;
    }
    case catalog::RecordingKind::session: {
      const auto session = model::io::read_rig_session(options.recording);
      if (!session.complete) {
        spdlog::warn("{}: the session was cut short; analysing what was recorded",
                     options.recording.string());
      }
      const auto a = catalog::analyze_session(session, threshold, analysis_options);
      result = catalog::to_json(a, threshold);
      if (!options.no_plots) {
        ensure_folder(plot_dir);
        if (a.friction) write_friction_figures(*a.friction, plot_dir, stem);
        if (a.vibration) write_vibration_figures(*a.vibration, plot_dir, stem);
      }
      break;
    }
  }
  if (options.output.empty()) {
    std::cout << result.dump(2) << "\n";
  } else {
    write_json_file(options.output, result);
    say_wrote(options.output);
  }
}

}  // namespace

void add_measure_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global) {
  auto options = std::make_shared<MeasureOptions>();
  auto* cmd =
      app.add_subcommand("measure", "Analyse one recording: descriptors as JSON and PNG figures");
  cmd->footer(
      "Analyse one recording and write its physical descriptors as JSON.\n"
      "A friction file (<tool>_<surface>_<load>N_<lever>_<rep>.csv[.gz]) gives the Coulomb\n"
      "coefficient `mu` with a 95 % interval and mu per speed; an accelerometer file\n"
      "(arm_<tool>_<surface>.csv[.gz]) gives the velocity-binned spectrum (`frequencies_hz`,\n"
      "`speeds_mm_s`, `amplitude_m_s2`) and the perceptually weighted descriptors; a rig session\n"
      "folder gives both. PNG figures go beside the output (or --plots).\n"
      "A file named otherwise is read with --tool and --surface (and for friction --load and\n"
      "--lever); its kind comes from its header, or --kind.");
  cmd->add_option("recording", options->recording, "Recording file or session folder")->required();
  cmd->add_option("-o,--output", options->output, "JSON output file (default: standard output)")
      ->check(file_to_write());
  cmd->add_option("--plots", options->plots,
                  "Folder for the PNG figures (default: beside -o, or .)");
  cmd->add_flag("--no-plots", options->no_plots, "Do not write figures");
  cmd->add_option("--threshold", options->threshold,
                  "Detection-threshold curve CSV (default: the bundled Israr et al. 2006 curve)")
      ->check(CLI::ExistingFile);
  auto& stated = options->stated;
  cmd->add_option_function<std::string>(
      "--tool", [&stated](const std::string& v) { stated.tool = v; },
      "Tool id, instead of the one in the file name (e.g. mixA)");
  cmd->add_option_function<std::string>(
      "--surface", [&stated](const std::string& v) { stated.surface = v; },
      "Surface id, instead of the one in the file name (e.g. note)");
  cmd->add_option_function<double>(
         "--load", [&stated](const double& v) { stated.normal_load_N = v; },
         fmt::format(
             "Friction files: normal load in N, instead of the file name's (the paper's: {:g})",
             rt::kReferenceNormalForce))
      ->check(in_range(model::io::kLightestFrictionLoadN, model::io::kHeaviestFrictionLoadN,
                       "a normal load in N"));
  cmd->add_option_function<double>(
         "--lever", [&stated](const double& v) { stated.lever_factor = v; },
         "Friction files: the arm's lever factor, instead of the file name's (13.3-14.1 in the "
         "paper's files)")
      ->check(in_range(model::io::kSmallestLeverFactor, model::io::kLargestLeverFactor, "a lever factor"));
  cmd->add_option("--kind", options->kind,
                  "accelerometer or friction (default: from the file name, else its header)")
      ->check(CLI::IsMember({"accelerometer", "friction"}));
  cmd->callback([options, global] {
    configure_logging(global->verbosity);
    measure(*options);
  });
}

}  // namespace nibrig::ui::cli
