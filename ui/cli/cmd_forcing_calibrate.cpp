// `nibrig forcing calibrate-material|calibrate-surface`: a new material's curve, or a new surface's
// forcing, calibrated from a few prints with the rest of a fitted model held
// (model/forcing/material_calibration.hpp, surface_calibration.hpp), with its uncertainty, written
// with -o and kept by name with --save. Without --forcing, the check on the catalog itself: the
// material or surface taken out of the fit, calibrated from a few of its prints, the rest predicted
// beside the model fitted on everything and the measurement's repeatability.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <optional>

#include "model/forcing/calibration_prints.hpp"
#include "model/forcing/forcing_file.hpp"
#include "model/forcing/forcing_store.hpp"
#include "model/forcing/material_calibration_check.hpp"
#include "model/forcing/material_calibration_study.hpp"
#include "model/forcing/measurement_repeatability.hpp"
#include "model/forcing/surface_calibration.hpp"
#include "model/forcing/surface_calibration_study.hpp"
#include "model/io/bundled_assets.hpp"
#include "model/measure/threshold_curve.hpp"
#include "ui/cli/commands.hpp"
#include "ui/cli/elapsed.hpp"
#include "ui/cli/forcing_calibration_json.hpp"
#include "ui/cli/forcing_options.hpp"
#include "ui/cli/knot_table.hpp"
#include "ui/cli/logging.hpp"
#include "ui/cli/output.hpp"
#include "ui/options/number_checks.hpp"

namespace nibrig::ui::cli {

namespace {

namespace forcing = model::forcing;

// What both verbs write: a file (-o), a stored name (--save, --replace to write over one) and the
// numbers printed (--json).
struct CalibrationOutput {
  std::filesystem::path output;
  std::string save;
  bool replace = false;
  std::filesystem::path json;
};

struct MaterialCalibrateOptions {
  ForcingInputOptions inputs;
  std::string material;
  std::vector<double> tips_mm{1.0, 4.0};
  std::string forcing_model;  // a file or a stored name; empty: the check on the catalog
  CalibrationOutput out;
};

struct SurfaceCalibrateOptions {
  ForcingInputOptions inputs;
  std::string surface;
  std::vector<std::string> tools;  // empty: every tool measured on it
  std::string forcing_model;
  std::size_t subsets = 200;
  CalibrationOutput out;
};

void add_calibration_output_options(CLI::App* cmd, CalibrationOutput& o) {
  cmd->add_option("-o,--output", o.output, "Write the calibrated forcing model to this file")
      ->check(file_to_write());
  cmd->add_option("--save", o.save,
                  "Keep the calibrated model under this name in the user store, for --forcing NAME "
                  "(" +
                      forcing::forcing_store_folder().string() + ")");
  cmd->add_flag("--replace", o.replace, "With --save: write over a model stored under that name");
  add_json_option(cmd, o.json, "the numbers printed");
}

void write_calibration_outputs(const forcing::ForcingModel& model, const CalibrationOutput& o) {
  if (!o.output.empty()) {
    ensure_folder(o.output.parent_path());
    forcing::write_forcing_model(o.output, model);
    say_wrote(o.output);
  }
  if (!o.save.empty()) {
    say_wrote(forcing::save_forcing_model(o.save, model, o.replace));
    std::cout << fmt::format("stored as '{}': `--forcing {}` predicts with it\n", o.save, o.save);
  }
}

// The measurement's repeatability from the catalog's prints recorded twice, when it has any.
std::optional<forcing::Repeatability> calibration_repeatability(const ForcingInputOptions& inputs) {
  const auto catalog =
      model::io::read_catalog(model::io::or_default(inputs.catalog, model::io::default_catalog));
  try {
    return forcing::nail_pair_repeatability(catalog);
  } catch (const std::invalid_argument& e) {
    std::cout << "no repeatability to compare with: " << e.what() << "\n";
    return std::nullopt;
  }
}

std::string repeatability_line(const std::optional<forcing::Repeatability>& r) {
  if (!r) return "";
  return fmt::format(
      "the measurement's repeatability: {:.2f} dB RMS (mean over {} prints recorded twice)\n",
      r->rms_db, r->pairs.size());
}

std::string versus_repeatability(double db, const std::optional<forcing::Repeatability>& r) {
  if (!r) return "";
  return fmt::format(" ({} the repeatability, {:.2f} dB)", db <= r->rms_db ? "within" : "beyond",
                     r->rms_db);
}

std::vector<double> calibration_metres(const std::vector<double>& mm) {
  std::vector<double> out;
  for (double d : mm) out.push_back(d * 1e-3);
  return out;
}

constexpr int kCalibrationLabelWidth = 30;

std::string calibrated_curve_rows(const forcing::MaterialCalibration& c) {
  return knot_table_header("gain (dB) at Hz", c.model.knot_frequencies_hz, kCalibrationLabelWidth) +
         knot_table_rows(c.material + " calibrated", c.log_gain, c.log_gain_se,
                         kCalibrationLabelWidth);
}

std::string calibration_uncertainty_note(const forcing::MaterialCalibration& c) {
  return fmt::format(
      "SE: the spread of its {} exemplars (cluster-robust, the surface forcing and tip curves "
      "held) and of its {} prints' own curves ({:.2f} dB between prints beyond that, pooled over "
      "the knots); t with {:.1f} degrees of freedom\n",
      c.exemplars, c.prints, forcing::log_gain_to_db(c.print_log_gain_sd), c.degrees_of_freedom);
}

// The check: the catalog's material taken as new, its other prints predicted.
void run_material_check(const MaterialCalibrateOptions& o, const ForcingInputs& inputs) {
  const auto repeatability = calibration_repeatability(o.inputs);
  const auto start = std::chrono::steady_clock::now();
  const auto threshold = model::measure::ThresholdCurve::load(model::io::default_threshold_curve());
  const forcing::MaterialCalibrationCheck check = forcing::check_material_calibration(
      inputs.exemplars, o.material, calibration_metres(o.tips_mm), {}, &threshold);
  const double seconds = seconds_since(start);
  const auto& c = check.calibration;
  std::string tips;
  for (double d : o.tips_mm) tips += (tips.empty() ? "" : ", ") + fmt::format("{:g} mm", d);
  std::cout << fmt::format(
      "{} taken as new: the model fitted without it, its curve calibrated from its {} prints ({} "
      "exemplars), its other prints predicted; {:.2f} s\n",
      o.material, tips, c.exemplars, seconds);
  std::cout << repeatability_line(repeatability);
  std::cout << fmt::format("{:<12}{:<11}{:>11}{:>14}{:>10}{:>17}{:>9}\n", "tool", "surface",
                           "calibrated", "uncalibrated", "full fit", "full fit w/o it", "SE (dB)");
  for (const bool calibration : {false, true}) {
    if (calibration) std::cout << "calibrated from (in sample):\n";
    for (const auto& p : check.prints)
      if (p.calibration_print == calibration)
        std::cout << fmt::format("{:<12}{:<11}{:>11.2f}{:>14.2f}{:>10.2f}{:>17.2f}{:>9.2f}\n",
                                 p.tool, p.surface, p.calibrated_rms_db, p.uncalibrated_rms_db,
                                 p.full_fit_rms_db, p.full_loo_rms_db, p.predicted_se_db);
  }
  if (check.predicted > 0)
    std::cout << fmt::format(
        "mean over the {} prints predicted: calibrated {:.2f} dB{}, uncalibrated (m = 1) {:.2f}, "
        "the model fitted on everything {:.2f}, and without each print {:.2f}\n",
        check.predicted, check.mean_calibrated_db,
        versus_repeatability(check.mean_calibrated_db, repeatability), check.mean_uncalibrated_db,
        check.mean_full_fit_db, check.mean_full_loo_db);
  else
    std::cout << "no print of " << o.material << " beyond the calibration's tips to predict\n";
  std::size_t mixes = 0;
  for (const auto& e : inputs.exemplars)
    if (e.material != o.material && e.material.find(o.material) != std::string::npos) ++mixes;
  std::cout << fmt::format("prints of a mix containing {} among the exemplars: {}\n", o.material,
                           mixes);
  std::cout << calibrated_curve_rows(c)
            << knot_table_rows(o.material + " (fit of everything)", check.full_fit_log_gain, {},
                               kCalibrationLabelWidth)
            << calibration_uncertainty_note(c);
  std::optional<forcing::MaterialStudy> study;
  if (check.predicted > 0) {
    // What each surface the calibration prints are measured on buys.
    study = forcing::study_material_calibration(inputs.exemplars, o.material,
                                                calibration_metres(o.tips_mm));
    std::cout << fmt::format(
        "the same prints measured on fewer surfaces (of the {} with every tip; mean over the sets "
        "of surfaces; more surfaces shrink the exemplars' part, only more prints the prints'):\n"
        "{:>9}{:>11}{:>16}{:>18}{:>15}\n",
        study->surfaces.size(), "surfaces", "exemplars", "SE of m (dB)", "exemplars' part",
        "predicted");
    for (const auto& step : study->steps)
      std::cout << fmt::format("{:>9}{:>11}{:>16.2f}{:>18.2f}{:>15.2f}\n", step.surfaces,
                               step.exemplars, step.se_rms_db, step.within_se_rms_db,
                               step.prediction_rms_db);
  }
  write_calibration_outputs(c.model, o.out);
  write_json_numbers(o.out.json, material_check_json(check, study ? &*study : nullptr, mixes,
                                                     seconds, repeatability));
}

// A lab's calibration against a model it has: the prints of the material at the tips asked for.
void run_material_calibration(const MaterialCalibrateOptions& o, const std::filesystem::path& file,
                              const forcing::ForcingModel& model, const ForcingInputs& inputs) {
  const auto tips = calibration_metres(o.tips_mm);
  const auto prints = forcing::prints_of_material(inputs.exemplars, o.material, tips);
  const forcing::MaterialCalibration c = forcing::calibrate_material(model, prints, o.material);
  std::cout << fmt::format(
      "{} calibrated against {} from {} prints ({} exemplars): residual {:.2f} dB RMS\n",
      o.material, file.string(), c.prints, c.exemplars, c.residual_rms_db);
  const auto repeatability = calibration_repeatability(o.inputs);
  std::cout << repeatability_line(repeatability);
  for (const auto& p : c.print_fits)
    std::cout << fmt::format("  {:<12}{:<11}{:>8.2f} dB (in sample)\n", p.tool, p.surface,
                             p.rms_db);
  const auto predicted =
      forcing::unused_print_errors(c.model, inputs.exemplars, o.material, prints);
  for (const auto& p : predicted)
    std::cout << fmt::format("  {:<12}{:<11}{:>8.2f} dB (predicted){}\n", p.tool, p.surface,
                             p.rms_db, versus_repeatability(p.rms_db, repeatability));
  std::cout << calibrated_curve_rows(c) << calibration_uncertainty_note(c);
  write_calibration_outputs(c.model, o.out);
  write_json_numbers(o.out.json,
                     material_calibration_json(c, tips, file, predicted, repeatability));
}

// The catalog's prints; against a model, on its grid (a lab's recordings have their own).
ForcingInputs calibration_inputs(ForcingInputOptions options,
                                 const forcing::ForcingModel* against) {
  if (against != nullptr) options.frequencies_hz = against->frequencies_hz;
  return load_forcing_inputs(options, design_progress());
}

// A model named but not there, or a name stored already, fail before the designs are simulated.
std::optional<std::pair<std::filesystem::path, forcing::ForcingModel>> calibration_model_first(
    const std::string& forcing_model, const CalibrationOutput& out) {
  if (!out.save.empty()) forcing::check_can_save(out.save, out.replace);
  if (forcing_model.empty()) return std::nullopt;
  const auto file = forcing::find_forcing_model(forcing_model);
  return std::pair{file, forcing::read_forcing_model(file)};
}

void run_calibrate_material(const MaterialCalibrateOptions& o) {
  const auto against = calibration_model_first(o.forcing_model, o.out);
  const ForcingInputs inputs = calibration_inputs(o.inputs, against ? &against->second : nullptr);
  std::cout << describe_inputs(inputs);
  if (against)
    run_material_calibration(o, against->first, against->second, inputs);
  else
    run_material_check(o, inputs);
}

// The study: the catalog's surface taken as new, calibrated from k of its tools for every k.
void run_surface_study(const SurfaceCalibrateOptions& o, const ForcingInputs& inputs) {
  const auto repeatability = calibration_repeatability(o.inputs);
  const auto start = std::chrono::steady_clock::now();
  const forcing::SurfaceStudy study =
      forcing::study_surface_calibration(inputs.exemplars, o.surface, o.subsets);
  const double seconds = seconds_since(start);
  std::cout << fmt::format(
      "{} taken as new: the model fitted without it, its forcing calibrated from k of its {} "
      "tools, the others predicted; {:.2f} s\n",
      o.surface, study.tools.size(), seconds);
  std::cout << repeatability_line(repeatability);
  std::cout << fmt::format("{:>6}{:>9}{:>16}{:>14}{:>16}\n", "tools", "subsets", "SE of F (dB)",
                           "predicted", "worst subset");
  for (const auto& s : study.steps)
    std::cout << fmt::format("{:>6}{:>9}{:>16}{:>14.2f}{:>16.2f}\n", s.tools, s.subsets,
                             s.tools >= 2 ? fmt::format("{:.2f}", s.se_rms_db) : "-",
                             s.prediction_rms_db, s.worst_subset_rms_db);
  std::cout << fmt::format(
      "the same tools under the model fitted on everything: {:.2f} dB, and without each tool "
      "{:.2f} dB\n",
      study.mean_full_fit_db, study.mean_full_loo_db);
  SurfaceStudyFindings findings;
  auto& fewest = findings.fewest_tools_se_within;
  if (repeatability) {
    fewest = study.fewest_tools_se_within(repeatability->rms_db);
    findings.fewest_tools_predicted_within = study.fewest_tools_within(repeatability->rms_db);
    const auto& predicted = findings.fewest_tools_predicted_within;
    std::cout << (fewest ? fmt::format("the calibration's SE is within the repeatability from {} "
                                       "tools",
                                       *fewest)
                         : std::string("the calibration's SE never comes within the repeatability"))
              << "; "
              << (predicted ? fmt::format("the tools left out are predicted within it from {}\n",
                                          *predicted)
                            : fmt::format("the tools left out are never predicted within it on "
                                          "the mean (with all but one tool: {:.2f} dB)\n",
                                          study.steps.back().prediction_rms_db));
  }
  const std::size_t k = fewest.value_or(2);
  if (k <= study.steps.size()) {
    findings.table_tools = k;
    const auto& step = study.steps[k - 1];
    std::cout << fmt::format(
        "each tool predicted from {} others (mean over the subsets leaving it "
        "out):\n"
        "{:<12}{:>11}{:>10}{:>17}\n",
        k, "tool", "predicted", "full fit", "full fit w/o it");
    for (std::size_t i = 0; i < study.tools.size(); ++i)
      std::cout << fmt::format("{:<12}{:>11.2f}{:>10.2f}{:>17.2f}\n", study.tools[i],
                               step.tool_rms_db[i], study.full_fit_rms_db[i],
                               study.full_loo_rms_db[i]);
  }
  std::optional<forcing::SurfaceCalibration> written;
  if (!o.out.output.empty() || !o.out.save.empty()) {
    // What is written: the surface calibrated from the tools asked for (all, by default) against
    // the model fitted without it.
    const auto threshold =
        model::measure::ThresholdCurve::load(model::io::default_threshold_curve());
    written = forcing::calibrate_held_out_surface(inputs.exemplars, o.surface, o.tools, &threshold);
    std::cout << fmt::format("written: {} calibrated from {} tools, SE of F {:.2f} dB RMS\n",
                             o.surface, written->tools.size(), written->rms_se_db);
    write_calibration_outputs(written->model, o.out);
    findings.written = &*written;
  }
  write_json_numbers(o.out.json, surface_study_json(study, findings, seconds, repeatability));
}

void run_surface_calibration(const SurfaceCalibrateOptions& o, const std::filesystem::path& file,
                             const forcing::ForcingModel& model, const ForcingInputs& inputs) {
  const auto tools = forcing::tools_on_surface(inputs.exemplars, o.surface, o.tools);
  const forcing::SurfaceCalibration c = forcing::calibrate_surface(model, tools, o.surface);
  const auto repeatability = calibration_repeatability(o.inputs);
  std::cout << repeatability_line(repeatability);
  std::cout << fmt::format("{} calibrated against {} from {} tools: residual {:.2f} dB RMS, ",
                           o.surface, file.string(), c.tools.size(), c.residual_rms_db)
            << (c.log_forcing_se.empty()
                    ? std::string("no uncertainty from one tool (measure a second)\n")
                    : fmt::format("SE of F {:.2f} dB RMS over the cells{}\n", c.rms_se_db,
                                  versus_repeatability(c.rms_se_db, repeatability)));
  for (const auto& t : c.tool_fits)
    std::cout << fmt::format("  {:<12}{:>8.2f} dB (in sample)\n", t.tool, t.rms_db);
  write_calibration_outputs(c.model, o.out);
  write_json_numbers(o.out.json, surface_calibration_json(c, file, repeatability));
}

void run_calibrate_surface(const SurfaceCalibrateOptions& o) {
  const auto against = calibration_model_first(o.forcing_model, o.out);
  const ForcingInputs inputs = calibration_inputs(o.inputs, against ? &against->second : nullptr);
  std::cout << describe_inputs(inputs);
  if (against)
    run_surface_calibration(o, against->first, against->second, inputs);
  else
    run_surface_study(o, inputs);
}

}  // namespace

void add_forcing_calibrate_commands(CLI::App* forcing_cmd,
                                    std::shared_ptr<const GlobalOptions> global) {
  auto m = std::make_shared<MaterialCalibrateOptions>();
  auto* material = forcing_cmd->add_subcommand(
      "calibrate-material", "Calibrate a new material's curve from a few prints of it");
  material->footer(
      "Fits the material's curve m(f) alone, the surface forcing and tip curves of a fitted model\n"
      "held, from the catalog's prints of it at the tips given (--tips), with per-knot standard\n"
      "errors (cluster-robust, a print on a surface per cluster) that predictions carry. With\n"
      "--forcing (a file or a stored name) against that model; without it, the check on the\n"
      "catalog: the material taken out of the fit, calibrated from those tips, and its other\n"
      "prints predicted beside the model fitted on everything and the repeatability.");
  add_forcing_input_options(material, m->inputs);
  material->add_option("--material", m->material, "The catalog's material to calibrate")
      ->required();
  material->add_option("--tips", m->tips_mm, "Tip diameters (mm) of the prints calibrated from")
      ->delimiter(',')
      ->capture_default_str()
      ->check(in_range(0.01, 1000, "a tip diameter in mm"));
  material->add_option("--forcing", m->forcing_model,
                       "Forcing model to calibrate against (a file or a stored name); default: "
                       "the check on the catalog");
  add_calibration_output_options(material, m->out);
  material->callback([m, global] {
    configure_logging(global->verbosity);
    run_calibrate_material(*m);
  });

  auto s = std::make_shared<SurfaceCalibrateOptions>();
  auto* surface = forcing_cmd->add_subcommand(
      "calibrate-surface", "Calibrate a new surface's forcing from tools the model knows");
  surface->footer(
      "Fits the surface's forcing F(f, v), every tool's H, tip and material curves held, from the\n"
      "catalog's tools measured on it (--tools, default all), with per-cell standard errors. With\n"
      "--forcing against that model; without it, the study on the catalog: the surface taken out\n"
      "of the fit and calibrated from k of its tools for every k, the others predicted, to say "
      "how\n"
      "many tools bring the uncertainty within the measurement's repeatability.");
  add_forcing_input_options(surface, s->inputs);
  surface->add_option("--surface", s->surface, "The catalog's surface to calibrate")->required();
  surface->add_option("--tools", s->tools, "Tools measured on it to calibrate from (default all)")
      ->delimiter(',');
  surface->add_option("--forcing", s->forcing_model,
                      "Forcing model to calibrate against (a file or a stored name); default: the "
                      "study on the catalog");
  surface
      ->add_option("--subsets", s->subsets,
                   "The study's most sets of k tools tried per k (all when fewer)")
      ->capture_default_str()
      ->check(whole_in_range(1, 100000, "a number of subsets"));
  add_calibration_output_options(surface, s->out);
  surface->callback([s, global] {
    configure_logging(global->verbosity);
    run_calibrate_surface(*s);
  });
}

}  // namespace nibrig::ui::cli
