// `nibrig forcing fit|loo`: the data-driven forcing model of Sec. 5.2 (Eq. 10) fitted to the
// printed tools of a catalog, and its leave-one-out validation (Fig. 12).
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>

#include "model/forcing/curve_jackknife.hpp"
#include "model/forcing/forcing_file.hpp"
#include "model/forcing/leave_one_out.hpp"
#include "model/forcing/leave_one_out_file.hpp"
#include "model/measure/threshold_curve.hpp"
#include "model/io/bundled_assets.hpp"
#include "ui/cli/commands.hpp"
#include "ui/cli/elapsed.hpp"
#include "ui/cli/forcing_figures.hpp"
#include "ui/cli/forcing_options.hpp"
#include "ui/cli/knot_table.hpp"
#include "ui/cli/logging.hpp"
#include "ui/cli/output.hpp"

namespace nibrig::ui::cli {

namespace {

namespace forcing = model::forcing;

struct FitCommandOptions {
  ForcingInputOptions inputs;
  std::filesystem::path output = "forcing.json";
  std::filesystem::path plots;
};

struct LooCommandOptions {
  ForcingInputOptions inputs;
  std::filesystem::path output;  // the table as CSV
  bool all = false;  // hold out every exemplar, not only the paper's tools
};

// One row per curve, its gain in dB at every knot, and under it the jackknife standard error of
// each knot (dB) when there is one.
std::string curves_table(const forcing::ForcingModel& model,
                         const forcing::CurveJackknife& jackknife) {
  const bool errors = jackknife.replicates.size() >= 2;
  constexpr int kLabelWidth = 22;
  std::string out = knot_table_header("gain (dB) at Hz", model.knot_frequencies_hz, kLabelWidth);
  auto row = [&](const std::string& label, const std::vector<double>& knots,
                 const std::vector<double>& standard_errors) {
    out += knot_table_rows(label, knots, standard_errors, kLabelWidth);
  };
  for (const auto& [d, knots] : model.tip_log_gain)
    row(fmt::format("tip {:g} mm{}", d * 1e3,
                    forcing::same_tip(d, model.reference_tip_diameter_m) ? " (ref)" : ""),
        knots, errors ? jackknife.tip_standard_errors(d) : std::vector<double>{});
  for (const auto& [m, knots] : model.material_log_gain)
    row(fmt::format("material {}{}", m, m == model.reference_material ? " (ref)" : ""), knots,
        errors ? jackknife.material_standard_errors(m) : std::vector<double>{});
  if (errors)
    out += fmt::format(
        "SE: delete-one-tool jackknife over {} printed tools{}\n", jackknife.replicates.size(),
        jackknife.not_left_out.empty()
            ? std::string()
            : fmt::format(" ({} could not be left out)", jackknife.not_left_out.size()));
  return out;
}

// How far held-out predictions' descriptors were from the measured ones: RMS of the log10 ratio,
// as a percentage, of the weighted mean and of the band energies, and the worst tool.
std::string descriptor_error_summary(const forcing::ForcingModel& model) {
  const forcing::DescriptorErrorSummary s = forcing::summarize(model.held_out_descriptor_errors);
  if (s.errors == 0) return "";
  return fmt::format(
      "predicted descriptors, each of {} exemplars held out: weighted mean vibration off by "
      "{:.1f} % RMS (worst {} on {}: {:+.1f} %), each of {} band energies by {:.1f} % RMS; "
      "predicted tools are placed with this error (forcing.json: held_out_descriptor_errors)\n",
      s.errors, forcing::percent_off(s.rms_log10_weighted_mean), s.worst->tool, s.worst->surface,
      forcing::percent_off(s.worst->log10_weighted_mean), forcing::kMaxDescriptorBands,
      forcing::percent_off(s.rms_log10_band_energy));
}

void run_fit(const FitCommandOptions& o) {
  ForcingInputs inputs = load_forcing_inputs(o.inputs, design_progress());
  std::cout << describe_inputs(inputs);
  const auto start = std::chrono::steady_clock::now();
  const forcing::ForcingModel model = fit_forcing_for_prediction(inputs).model;
  const double fit_seconds = seconds_since(start);

  const auto [best, worst] =
      std::minmax_element(model.exemplar_fits.begin(), model.exemplar_fits.end(),
                          [](const auto& a, const auto& b) { return a.rms_db < b.rms_db; });
  std::cout << fmt::format(
      "fit: {} observations ({} amplitudes <= 0 skipped), residual RMS {:.2f} dB; per exemplar "
      "{:.2f} ({} on {}) to {:.2f} dB ({} on {}); {:.3f} s with the leave-one-out fits\n",
      model.observations, model.skipped_nonpositive, model.residual_rms_db, best->rms_db,
      best->tool, best->surface, worst->rms_db, worst->tool, worst->surface, fit_seconds);
  std::cout << descriptor_error_summary(model);
  const forcing::CurveJackknife jackknife = forcing::jackknife_curves(inputs.exemplars);
  std::cout << curves_table(model, jackknife);
  for (const auto& why : jackknife.not_left_out) spdlog::info("jackknife: not left out: {}", why);
  ensure_folder(o.output.parent_path());
  forcing::write_forcing_model(o.output, model);
  say_wrote(o.output);
  if (!o.plots.empty()) {
    ensure_folder(o.plots);
    plot_scaling_curves(model, o.plots, &jackknife);
    say_wrote(o.plots / "tip_curves.png");
    say_wrote(o.plots / "material_curves.png");
  }
}

void run_loo(const LooCommandOptions& o) {
  ForcingInputs inputs = load_forcing_inputs(o.inputs, design_progress());
  std::cout << describe_inputs(inputs);
  std::vector<std::size_t> held;
  for (std::size_t e = 0; e < inputs.exemplars.size(); ++e)
    if (o.all || forcing::is_paper_tool(inputs.exemplars[e])) held.push_back(e);
  if (held.empty())
    throw std::runtime_error(
        "no paper tool (vero, DM95 or DM85 with a 1, 2 or 4 mm tip on office, note or stone) "
        "among the exemplars; --all holds out every exemplar instead");

  const auto start = std::chrono::steady_clock::now();
  const auto threshold = model::measure::ThresholdCurve::load(model::io::default_threshold_curve());
  const forcing::LeaveOneOut loo = forcing::leave_one_out(inputs.exemplars, held, {}, &threshold);
  const double seconds = seconds_since(start);
  const auto& speeds = inputs.exemplars.front().measured.speeds_m_s;

  std::string header = fmt::format("{:<12}{:<11}{:>8}{:>10}  RMS dB at mm/s:", "tool", "surface",
                                   "RMS dB", "baseline");
  for (double v : speeds) header += fmt::format("{:>7.0f}", v * 1e3);
  std::cout << header << "\n";
  for (const auto& r : loo.results) {
    std::string line = fmt::format("{:<12}{:<11}", r.tool, r.surface);
    if (r.predictable) {
      line += fmt::format("{:>8.2f}{:>10.2f}  {:15}", r.rms_db, r.baseline_rms_db, "");
      for (double e : r.rms_db_by_speed) line += fmt::format("{:>7.2f}", e);
    } else {
      line += "  not predictable: " + r.reason;
    }
    std::cout << line << "\n";
  }
  const auto& s = loo.summary;
  std::cout << fmt::format(
      "held out {} ({} predicted, {} not predictable) in {:.2f} s; RMS dB mean {:.2f}, median "
      "{:.2f}, max {:.2f}; baseline (geometric mean of the other tools on the surface) mean "
      "{:.2f}; perceptually weighted mean vibration off by {:.1f} % RMS\n",
      loo.results.size(), s.predicted, s.not_predictable, seconds, s.mean_rms_db, s.median_rms_db,
      s.max_rms_db, s.mean_baseline_rms_db, forcing::percent_off(s.weighted_mean_rms_log10));
  if (!s.worst.empty()) {
    std::string worst = "worst:";
    for (std::size_t k = 0; k < s.worst.size(); ++k) {
      const auto& r = loo.results[s.worst[k]];
      worst += fmt::format("{} {} on {} ({:.2f} dB)", k ? "," : "", r.tool, r.surface, r.rms_db);
    }
    std::cout << worst << "\n";
  }
  if (!o.output.empty()) {
    ensure_folder(o.output.parent_path());
    forcing::write_leave_one_out_csv(o.output, loo, speeds);
    say_wrote(o.output);
  }
}

}  // namespace

void add_forcing_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global) {
  auto* forcing_cmd = app.add_subcommand(
      "forcing", "Data-driven forcing model: surface forcing, tip and material curves (Sec. 5.2)");
  forcing_cmd->require_subcommand(1);

  auto fit_options = std::make_shared<FitCommandOptions>();
  auto* fit = forcing_cmd->add_subcommand("fit", "Fit Eq. 10 to a catalog's printed tools");
  fit->footer(
      "Every printed tool with a material, a tip diameter and a vibration spectrum is an "
      "exemplar;\n"
      "its response H comes from its simulated design. Fits the surface forcing F_S(f, v), a tip\n"
      "curve per diameter and a material curve per material (log gains, Hermite knots every 50\n"
      "Hz, the 2 mm VeroClear tool as reference) and writes them as forcing.json.");
  add_forcing_input_options(fit, fit_options->inputs);
  fit->add_option("-o,--output", fit_options->output, "Forcing model JSON to write")
      ->capture_default_str()
      ->check(file_to_write());
  fit->add_option("--plots", fit_options->plots,
                  "Also write tip_curves.png and material_curves.png (Fig. 13) to this folder");
  fit->callback([fit_options, global] {
    configure_logging(global->verbosity);
    run_fit(*fit_options);
  });

  auto loo_options = std::make_shared<LooCommandOptions>();
  auto* loo = forcing_cmd->add_subcommand("loo", "Leave-one-out validation of the fit (Fig. 12)");
  loo->footer(
      "Holds out each of the paper's tools ({vero, DM95, DM85} x {1, 2, 4 mm} on office, note and\n"
      "stone) in turn, fits the rest and predicts it: RMS of 20 log10(predicted/measured) over "
      "all\n"
      "bins and speeds, and per speed, beside a baseline (the geometric mean of the other tools "
      "on\n"
      "the same surface).");
  add_forcing_input_options(loo, loo_options->inputs);
  loo->add_option("-o,--output", loo_options->output, "Write the table as CSV")
      ->check(file_to_write());
  loo->add_flag("--all", loo_options->all, "Hold out every exemplar, not only the paper's tools");
  loo->callback([loo_options, global] {
    configure_logging(global->verbosity);
    run_loo(*loo_options);
  });

  add_forcing_holdout_command(forcing_cmd, global);
  add_forcing_calibrate_commands(forcing_cmd, global);
}

}  // namespace nibrig::ui::cli
