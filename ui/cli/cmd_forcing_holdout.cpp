// `nibrig forcing holdout`: the check of Sec. 5.3 on measured designs. Every printed tool with one
// tip diameter is held out, the model is fitted to the rest, and each held-out tool is predicted
// with its tip curve interpolated between the fitted neighbours — against the no-interpolation
// baselines of Fig. 14 (the same simulation with a neighbour's curve) and against the measured
// neighbours themselves, overall and per speed; then, from a fit of every tool, how large the tip
// effect is and how far the held-out curve lies from the interpolation, against their errors.
// With --material, the same on the material axis: a material held out and predicted as a mix of
// two others (design/material_hold_out.hpp).
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <iostream>
#include <span>

#include "model/design/hold_out_file.hpp"
#include "model/design/interpolation_check.hpp"
#include "model/design/material_hold_out.hpp"
#include "model/forcing/curve_jackknife.hpp"
#include "model/mechanics/material_table.hpp"
#include "model/io/bundled_assets.hpp"
#include "ui/cli/commands.hpp"
#include "ui/cli/elapsed.hpp"
#include "ui/cli/forcing_options.hpp"
#include "ui/cli/interpolation_report.hpp"
#include "ui/cli/knot_table.hpp"
#include "ui/cli/logging.hpp"
#include "ui/options/number_checks.hpp"
#include "ui/cli/output.hpp"

namespace nibrig::ui::cli {

namespace {

namespace design = model::design;
namespace forcing = model::forcing;

struct HoldoutOptions {
  ForcingInputOptions inputs;
  double tip_mm = 2.0;
  std::string material;  // set: hold out this material instead of a tip
  std::vector<std::string> mix_of{"vero", "DM85"};
  double fraction = -1.0;  // of the mix's second material; < 0: equal modulus
  std::filesystem::path output;  // errors per tool and speed as CSV
  std::filesystem::path plots;
};

// What the tip and the material hold-outs report alike: the held-out predictions and how to name
// their two neighbours (the smaller and larger tip, or the mix's two materials).
struct HoldoutView {
  const forcing::ForcingModel* model = nullptr;
  std::span<const design::InterpolatedPrediction> predictions;
  std::array<std::string, 2> neighbour;                   // "1 mm", "4 mm" or "vero", "DM85"
  design::HoldOutColumns columns;                         // of the CSV
  std::function<design::DesignPoint(const design::InterpolatedPrediction&)> point_of;
};

// The per-knot tables of what the data resolve: values over their standard errors, in dB.
constexpr int kLabelWidth = 34;

std::string knot_rows(const std::string& label, const std::vector<double>& value,
                      const std::vector<double>& se) {
  return knot_table_rows(label, value, se, kLabelWidth);
}

std::string knot_header(const std::vector<double>& knots, std::size_t tools) {
  return fmt::format(
             "what the data resolve (all tools fitted; SE: delete-one-tool jackknife over {} "
             "tools):\n",
             tools) +
         knot_table_header("dB at Hz", knots, kLabelWidth);
}

// The tip effect and the held-out curve's departure from the interpolation, per knot in dB with
// their standard errors, and at how many knots each exceeds two of them.
std::string resolution_table(const design::TipResolution& r) {
  const std::string lower = forcing::tip_label(r.lower_tip_m),
                    upper = forcing::tip_label(r.upper_tip_m);
  const auto& knots = r.knot_frequencies_hz;
  return knot_header(knots, r.tools) +
         knot_rows(fmt::format("{} − {} (the tip effect)", upper, lower), r.effect, r.effect_se) +
         knot_rows(fmt::format("{} − the line {}–{}", forcing::tip_label(r.tip_m), lower, upper),
                   r.deviation, r.deviation_se) +
         fmt::format(
             "the tip effect exceeds twice its SE at {} of {} knots; the {} curve departs "
             "from the interpolation by more than twice its SE at {} of {}\n",
             r.effect_resolved_knots(), knots.size(), forcing::tip_label(r.tip_m),
             r.deviation_resolved_knots(), knots.size());
}

// The same for a material held out as a mix, and the fraction its curve lies at.
std::string resolution_table(const design::MaterialResolution& r) {
  const auto& knots = r.knot_frequencies_hz;
  return knot_header(knots, r.tools) +
         knot_rows(fmt::format("{} − {} (the material effect)", r.second, r.first), r.effect,
                   r.effect_se) +
         knot_rows(fmt::format("{} − the mix ({:.3f} {})", r.material, r.second_fraction, r.second),
                   r.deviation, r.deviation_se) +
         fmt::format(
             "the material effect exceeds twice its SE at {} of {} knots; the {} curve departs "
             "from the mix's interpolation by more than twice its SE at {} of {}; its curve lies "
             "at a fraction {:.2f} ± {:.2f} (SE) of {} on the line {}–{} (least squares over the "
             "knots), the mix predicted at {:.3f}\n",
             r.effect_resolved_knots(), knots.size(), r.material, r.deviation_resolved_knots(),
             knots.size(), r.fitted_fraction, r.fitted_fraction_se, r.second, r.first, r.second,
             r.second_fraction);
}

// The table per tool, the means per speed, the summary line, and the CSV and figures asked for.
void report_holdout(const HoldoutView& v, std::span<const forcing::ForcingExemplar> exemplars,
                    const HoldoutOptions& o) {
  const std::string first_curve = v.neighbour[0] + " curve",
                    second_curve = v.neighbour[1] + " curve";
  std::cout << fmt::format("{:<10}{:<11}{:>13}{:>13}{:>13}{:>12}{:>15}{:>15}\n", "tool", "surface",
                           "interpolated", first_curve, second_curve, "beats both",
                           "measured " + v.neighbour[0], "measured " + v.neighbour[1]);
  const auto& speeds = v.model->speeds_m_s;
  for (const auto& r : v.predictions) {
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
                             measured(r.measured_neighbour_rms_db[0]),
                             measured(r.measured_neighbour_rms_db[1]));
  }
  const design::HoldOutSummary summary = design::summarize(v.predictions);
  const int predicted = summary.predicted;
  if (predicted == 0) throw std::runtime_error("no held-out tool could be predicted");

  std::cout << fmt::format(
      "by speed, mean RMS dB over the {} predicted:\n{:>14}{:>13}{:>13}{:>13}{:>12}\n", predicted,
      "speed (mm/s)", "interpolated", first_curve, second_curve, "beats both");
  for (std::size_t s = 0; s < speeds.size(); ++s)
    std::cout << fmt::format("{:>14.1f}{:>13.2f}{:>13.2f}{:>13.2f}{:>12}\n", speeds[s] * 1e3,
                             summary.mean_predicted_db_by_speed[s],
                             summary.mean_baseline_db_by_speed[0][s],
                             summary.mean_baseline_db_by_speed[1][s],
                             fmt::format("{} of {}", summary.beats_every_baseline_by_speed[s], predicted));
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

  if (!o.output.empty()) {
    ensure_folder(o.output.parent_path());
    design::write_hold_out_csv(o.output, v.predictions, v.model->speeds_m_s, v.columns);
    say_wrote(o.output);
  }
  if (!o.plots.empty()) {
    ensure_folder(o.plots);
    for (const auto& r : v.predictions) {
      if (!r.not_predictable.empty()) continue;
      const auto e = std::find_if(exemplars.begin(), exemplars.end(), [&](const auto& x) {
        return x.tool == r.tool && x.surface == r.surface;
      });
      write_interpolation_figure(*v.model, v.point_of(r), r.surface, e->response_magnitude,
                                 r.tool + " (measured, held out)", e->measured,
                                 o.plots / (r.tool + "_" + r.surface + ".png"));
    }
    std::cout << "wrote " << predicted << " figures like Fig. 14 to " << o.plots.string() << "\n";
  }
}

void run_tip_holdout(const HoldoutOptions& o) {
  const ForcingInputs inputs = load_forcing_inputs(o.inputs, design_progress());
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
  HoldoutView v;
  v.model = &held.model;
  v.predictions = held.predictions;
  v.neighbour = {lower, upper};
  v.columns = design::tip_hold_out_columns(held.lower_tip_m, held.upper_tip_m);
  v.point_of = [](const design::InterpolatedPrediction& r) {
    return design::DesignPoint{{{r.material, 1.0}}, r.tip_diameter_m};
  };
  report_holdout(v, inputs.exemplars, o);
  std::cout << resolution_table(
      design::tip_resolution(forcing::jackknife_curves(inputs.exemplars), tip_m));
}

void run_material_holdout(const HoldoutOptions& o) {
  if (o.mix_of.size() != 2)
    throw CLI::ValidationError("--as", "takes two materials, the mix's first and second");
  const std::string &first = o.mix_of[0], &second = o.mix_of[1];
  std::string why;
  double fraction = o.fraction;
  if (fraction < 0) {
    const auto materials = model::mechanics::read_material_table(
        o.inputs.materials.empty() ? model::io::default_materials() : o.inputs.materials);
    fraction = design::equal_modulus_fraction(materials, o.material, first, second);
    why = fmt::format(
        ", the mix with {}'s Young's modulus by the rule of mixtures the mechanics uses",
        o.material);
  }
  // The fraction first: a mix that cannot be made fails before the designs are meshed.
  const ForcingInputs inputs = load_forcing_inputs(o.inputs, design_progress());
  std::cout << describe_inputs(inputs);
  const auto start = std::chrono::steady_clock::now();
  const design::MaterialHoldOut held =
      design::hold_out_material(inputs.exemplars, o.material, first, second, fraction);
  const double seconds = seconds_since(start);
  std::cout << fmt::format(
      "held out the {} tools ({}): fitted on the rest, each predicted at its tip as {:.3f} {} + "
      "{:.3f} {} (m interpolated linearly in the fraction{}); {:.2f} s\n",
      o.material, held.predictions.size(), 1 - fraction, first, fraction, second, why, seconds);
  HoldoutView v;
  v.model = &held.model;
  v.predictions = held.predictions;
  v.neighbour = {first, second};
  v.columns = design::material_hold_out_columns(first, second);
  v.point_of = [&](const design::InterpolatedPrediction& r) {
    return held.point_at(r.tip_diameter_m);
  };
  report_holdout(v, inputs.exemplars, o);
  std::cout << resolution_table(design::material_resolution(
      forcing::jackknife_curves(inputs.exemplars), o.material, first, second, fraction));
}

void run_holdout(const HoldoutOptions& o) {
  if (o.material.empty())
    run_tip_holdout(o);
  else
    run_material_holdout(o);
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
      "jackknife standard errors. --material holds out a material instead, each of its tools\n"
      "predicted as a mix of two others (--as, default vero,DM85) at its own tip, and reports\n"
      "the fraction the fitted curves put it at beside the one predicted with.");
  add_forcing_input_options(cmd, o->inputs);
  auto* tip = cmd->add_option("--tip", o->tip_mm, "Tip diameter to hold out, mm")
                  ->capture_default_str()
                  ->check(in_range(0.01, 1000, "a tip diameter in mm"));
  auto* material = cmd->add_option(
      "--material", o->material, "Hold out this material instead (e.g. DM95), predicted as a mix");
  material->excludes(tip);
  cmd->add_option("--as", o->mix_of, "The mix's two materials, with --material")
      ->expected(2)
      ->delimiter(',')
      ->capture_default_str()
      ->needs(material);
  cmd->add_option("--fraction", o->fraction,
                  "Fraction of the second material (default: the mix with the held-out "
                  "material's Young's modulus)")
      ->check(in_range(0, 1, "a fraction"))
      ->needs(material);
  cmd->add_option("-o,--output", o->output, "Write the errors per tool and speed as CSV")
      ->check(file_to_write());
  cmd->add_option("--plots", o->plots, "Also write a figure like Fig. 14 per held-out tool here");
  cmd->callback([o, global] {
    configure_logging(global->verbosity);
    run_holdout(*o);
  });
}

}  // namespace nibrig::ui::cli
