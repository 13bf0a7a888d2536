// `nibrig forcing holdout`: the check of Sec. 5.3 on measured designs. Every printed tool with one
// tip diameter is held out, the model is fitted to the rest, and each held-out tool is predicted
// with its tip curve interpolated between the fitted neighbours — against the no-interpolation
// baselines of Fig. 14 (the same simulation with a neighbour's curve) and against the measured
// neighbours themselves, overall and per speed; then, from a fit of every tool, how large the tip
// effect is and how far the held-out curve lies from the interpolation, against their errors.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <sstream>

#include "model/design/interpolation_check.hpp"
#include "model/forcing/curve_jackknife.hpp"
#include "ui/cli/commands.hpp"
#include "ui/cli/elapsed.hpp"
#include "ui/cli/forcing_inputs.hpp"
#include "ui/cli/interpolation_report.hpp"
#include "ui/cli/logging.hpp"
#include "ui/cli/output.hpp"

namespace nibrig::ui::cli {

namespace {

namespace design = model::design;
namespace forcing = model::forcing;

struct HoldoutOptions {
  ForcingInputOptions inputs;
  double tip_mm = 2.0;
  std::filesystem::path csv;
  std::filesystem::path plots;
};

// One row per held-out tool and speed, and one per tool over all speeds (speed "all").
std::string holdout_csv(const design::TipHoldOut& held, const std::vector<double>& speeds_m_s) {
  std::ostringstream csv;
  csv << "tool,surface,speed_mm_s,interpolated_rms_db,"
      << fmt::format("tip_{:g}mm_curve_rms_db,tip_{:g}mm_curve_rms_db,", held.lower_tip_m * 1e3,
                     held.upper_tip_m * 1e3)
      << "measured_lower_tip_rms_db,measured_upper_tip_rms_db,not_predictable\n";
  for (const auto& r : held.predictions) {
    const auto& c = r.comparison;
    const auto measured = [](double rms) {
      return rms < 0 ? std::string() : fmt::format("{}", rms);
    };
    if (!r.not_predictable.empty()) {
      csv << fmt::format("{},{},all,,,,,,\"{}\"\n", r.tool, r.surface, r.not_predictable);
      continue;
    }
    for (std::size_t s = 0; s < speeds_m_s.size(); ++s)
      csv << fmt::format("{},{},{:g},{},{},{},,,\n", r.tool, r.surface, speeds_m_s[s] * 1e3,
                         c.interpolated.rms_db_by_speed[s], c.baselines[0].error.rms_db_by_speed[s],
                         c.baselines[1].error.rms_db_by_speed[s]);
    csv << fmt::format("{},{},all,{},{},{},{},{},\n", r.tool, r.surface, c.interpolated.rms_db,
                       c.baselines[0].error.rms_db, c.baselines[1].error.rms_db,
                       measured(r.lower_measured_rms_db), measured(r.upper_measured_rms_db));
  }
  return csv.str();
}

// The tip effect and the held-out curve's departure from the interpolation, per knot in dB with
// their standard errors, and at how many knots each exceeds two of them.
std::string resolution_table(const design::TipResolution& r) {
  const std::string lower = forcing::tip_label(r.lower_tip_m),
                    upper = forcing::tip_label(r.upper_tip_m);
  std::string out = fmt::format(
      "what the data resolve (all tools fitted; SE: delete-one-tool jackknife over {} tools):\n"
      "{:<34}",
      r.tools, "dB at Hz");
  for (double f : r.knot_frequencies_hz) out += fmt::format("{:>7g}", f);
  out += "\n";
  const auto rows = [&](const std::string& label, const std::vector<double>& value,
                        const std::vector<double>& se) {
    out += fmt::format("{:<34}", label);
    for (double v : value) out += fmt::format("{:>7.2f}", forcing::log_gain_to_db(v));
    out += fmt::format("\n{:<34}", "  ± (SE)");
    for (double e : se) out += fmt::format("{:>7.2f}", forcing::log_gain_to_db(e));
    out += "\n";
  };
  rows(fmt::format("{} − {} (the tip effect)", upper, lower), r.effect, r.effect_se);
  rows(fmt::format("{} − the line {}–{}", forcing::tip_label(r.tip_m), lower, upper), r.deviation,
       r.deviation_se);
  const std::size_t knots = r.knot_frequencies_hz.size();
  return out + fmt::format(
                   "the tip effect exceeds twice its SE at {} of {} knots; the {} curve departs "
                   "from the interpolation by more than twice its SE at {} of {}\n",
                   r.effect_resolved_knots(), knots, forcing::tip_label(r.tip_m),
                   r.deviation_resolved_knots(), knots);
}

void run_holdout(const HoldoutOptions& o) {
  ForcingInputs inputs = load_forcing_inputs(o.inputs);
  std::cout << describe_inputs(inputs);
  const double tip_m = o.tip_mm * 1e-3;
  const auto start = std::chrono::steady_clock::now();
  const design::TipHoldOut held = design::hold_out_tip(inputs.exemplars, tip_m);
  const double seconds = seconds_since(start);
  const std::string lower = forcing::tip_label(held.lower_tip_m);
  const std::string upper = forcing::tip_label(held.upper_tip_m);
  std::cout << fmt::format(
      "held out the {} tools ({}): fitted on the rest (reference tip {}), t interpolated between "
      "{} and {}; {:.2f} s\n",
      forcing::tip_label(tip_m), held.predictions.size(), lower, lower, upper, seconds);

  const std::string lower_curve = lower + " curve", upper_curve = upper + " curve";
  std::cout << fmt::format("{:<10}{:<11}{:>13}{:>13}{:>13}{:>12}{:>15}{:>15}\n", "tool", "surface",
                           "interpolated", lower_curve, upper_curve, "beats both",
                           "measured " + lower, "measured " + upper);
  const auto& speeds = held.model.speeds_m_s;
  std::vector<double> sum_by_speed(speeds.size()), lower_by_speed(speeds.size()),
      upper_by_speed(speeds.size());
  std::vector<int> beats_by_speed(speeds.size());
  for (const auto& r : held.predictions) {
    if (!r.not_predictable.empty()) {
      std::cout << fmt::format("{:<10}{:<11}  not predictable: {}\n", r.tool, r.surface,
                               r.not_predictable);
      continue;
    }
    const auto& c = r.comparison;
    const auto measured = [](double rms) {
      return rms < 0 ? std::string("-") : fmt::format("{:.2f}", rms);
    };
    std::cout << fmt::format("{:<10}{:<11}{:>13.2f}{:>13.2f}{:>13.2f}{:>12}{:>15}{:>15}\n", r.tool,
                             r.surface, c.interpolated.rms_db, c.baselines[0].error.rms_db,
                             c.baselines[1].error.rms_db, c.beats_every_baseline() ? "yes" : "no",
                             measured(r.lower_measured_rms_db), measured(r.upper_measured_rms_db));
    for (std::size_t s = 0; s < speeds.size(); ++s) {
      const double e = c.interpolated.rms_db_by_speed[s];
      const double l = c.baselines[0].error.rms_db_by_speed[s];
      const double u = c.baselines[1].error.rms_db_by_speed[s];
      sum_by_speed[s] += e, lower_by_speed[s] += l, upper_by_speed[s] += u;
      beats_by_speed[s] += e < l && e < u;
    }
  }
  const design::TipHoldOutSummary summary = design::summarize(held);
  const int predicted = summary.predicted;
  if (predicted == 0) throw std::runtime_error("no held-out tool could be predicted");

  std::cout << fmt::format(
      "by speed, mean RMS dB over the {} predicted:\n{:>14}{:>13}{:>13}{:>13}{:>12}\n", predicted,
      "speed (mm/s)", "interpolated", lower_curve, upper_curve, "beats both");
  for (std::size_t s = 0; s < speeds.size(); ++s)
    std::cout << fmt::format("{:>14.1f}{:>13.2f}{:>13.2f}{:>13.2f}{:>12}\n", speeds[s] * 1e3,
                             sum_by_speed[s] / predicted, lower_by_speed[s] / predicted,
                             upper_by_speed[s] / predicted,
                             fmt::format("{} of {}", beats_by_speed[s], predicted));
  std::cout << fmt::format(
      "interpolation beats both no-interpolation baselines (Fig. 14) on {} of {} held-out tools",
      summary.beats_every_baseline, predicted);
  if (summary.compared_with_measured > 0)
    std::cout << fmt::format(
        "; the prediction is closer than a measured neighbour in {} of {} comparisons (mean {:.2f} "
        "vs {:.2f} dB)",
        summary.closer_than_measured, summary.compared_with_measured, summary.mean_predicted_db,
        summary.mean_measured_db);
  std::cout << "\n";

  std::cout << resolution_table(
      design::tip_resolution(forcing::jackknife_curves(inputs.exemplars), tip_m));

  if (!o.csv.empty()) {
    write_text_file(o.csv, holdout_csv(held, speeds));
    std::cout << "wrote " << o.csv.string() << "\n";
  }
  if (!o.plots.empty()) {
    ensure_folder(o.plots);
    for (const auto& r : held.predictions) {
      if (!r.not_predictable.empty()) continue;
      const auto e =
          std::find_if(inputs.exemplars.begin(), inputs.exemplars.end(),
                       [&](const auto& x) { return x.tool == r.tool && x.surface == r.surface; });
      const design::DesignPoint point{{{r.material, 1.0}}, r.tip_diameter_m};
      write_interpolation_figure(held.model, point, r.surface, e->response_magnitude,
                                 r.tool + " (measured, held out)", e->measured,
                                 o.plots / (r.tool + "_" + r.surface + ".png"));
    }
    std::cout << "wrote " << predicted << " figures like Fig. 14 to " << o.plots.string() << "\n";
  }
}

}  // namespace

void add_forcing_holdout_command(CLI::App* forcing_cmd,
                                 std::shared_ptr<const GlobalOptions> global) {
  auto o = std::make_shared<HoldoutOptions>();
  auto* cmd = forcing_cmd->add_subcommand(
      "holdout", "Predict measured tools of one tip size from the others (Sec. 5.3, Fig. 14)");
  cmd->footer(
      "Holds out every printed tool with the given tip, fits the rest (the smallest remaining tip\n"
      "as reference) and predicts each held-out tool with its own simulated response and the tip\n"
      "curve interpolated between the fitted neighbours. Reports the RMS dB error overall and per\n"
      "speed beside the no-interpolation baselines (the same prediction with either neighbour's\n"
      "curve: Fig. 14's grey lines) and the measured neighbours taken as they are. Then, from a\n"
      "fit of every tool, what the data resolve: the tip effect between the neighbours and the\n"
      "held-out curve's departure from the interpolation, per knot with delete-one-tool\n"
      "jackknife standard errors.");
  add_forcing_input_options(cmd, o->inputs);
  cmd->add_option("--tip", o->tip_mm, "Tip diameter to hold out, mm")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd->add_option("--csv", o->csv, "Also write the errors per tool and speed as CSV");
  cmd->add_option("--plots", o->plots, "Also write a figure like Fig. 14 per held-out tool here");
  cmd->callback([o, global] {
    configure_logging(global->verbosity);
    run_holdout(*o);
  });
}

}  // namespace nibrig::ui::cli
