// `nibrig predict`: how a design that was never printed will measure on a surface (Sec. 5.3) —
// its velocity-binned spectrum, friction and descriptors in the JSON layout `nibrig measure` writes
// for a real recording, so the two compare directly; with a measurement, its error per speed
// against the no-interpolation baselines of Fig. 14, and a PNG of all of them.
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>

#include "model/design/mixed_design.hpp"
#include "model/design/no_interpolation_baseline.hpp"
#include "model/design/predicted_tool.hpp"
#include "model/forcing/forcing_file.hpp"
#include "model/forcing/leave_one_out.hpp"
#include "model/io/catalog_file.hpp"
#include "model/io/format_error.hpp"
#include "model/io/json_fields.hpp"
#include "model/io/bundled_assets.hpp"
#include "model/mechanics/material_table.hpp"
#include "ui/cli/commands.hpp"
#include "model/design/prediction_file.hpp"
#include "ui/cli/design_reports.hpp"
#include "ui/cli/elapsed.hpp"
#include "ui/cli/interpolation_report.hpp"
#include "ui/cli/logging.hpp"
#include "ui/options/number_checks.hpp"
#include "ui/cli/output.hpp"
#include "ui/cli/forcing_options.hpp"
#include "ui/report/figures.hpp"

namespace nibrig::ui::cli {

namespace {

namespace design = model::design;
namespace forcing = model::forcing;
namespace mech = model::mechanics;

struct PredictOptions {
  std::string design;  // a design.json or a design point ("DM85:0.25,vero:0.75,tip=1mm")
  std::string surface;
  std::filesystem::path forcing_model;  // empty: fit on the catalog now
  ForcingInputOptions inputs;           // catalog, template, materials, modes, mesh size
  std::filesystem::path output = "predicted.json";
  std::filesystem::path measured;  // a `nibrig measure` JSON to compare with
  std::string against;             // or a catalog tool measured on the surface
  std::filesystem::path plot;
};

// The measured spectrum to compare with: a `nibrig measure` output, or the catalog's pairing.
std::optional<std::pair<std::string, model::io::VelocitySpectrum>> measurement(
    const PredictOptions& o, const model::io::Catalog& catalog) {
  if (!o.measured.empty()) {
    const auto json = model::io::json_fields::parse_file(o.measured);
    return std::pair{o.measured.filename().string(),
                     model::io::velocity_spectrum_from_json(json, o.measured, "")};
  }
  if (o.against.empty()) return std::nullopt;
  for (const auto& p : catalog.pairings)
    if (p.tool == o.against && p.surface == o.surface && p.vibration)
      return std::pair{o.against + " on " + o.surface + " (measured)", p.vibration->spectrum};
  throw std::invalid_argument("--against: the catalog has no vibration spectrum of '" + o.against +
                              "' on '" + o.surface + "'");
}

void run_predict(const PredictOptions& o) {
  // The design first, so that a bad one fails before a forcing model is fitted: a design file is
  // used as it is, a design point is built on the printed tools' template.
  std::optional<mech::Design> own;
  design::DesignPoint point;
  if (o.design.ends_with(".json")) {
    own = mech::read_design(
        o.design, mech::read_material_table(o.inputs.materials.empty() ? model::io::default_materials()
                                                                       : o.inputs.materials));
    point = design::design_point_of(*own);
  } else {
    point = design::parse_design_point(o.design);
  }
  // The time reported includes reading or fitting the default forcing model: a first fit is most of
  // the wait, and a time that leaves it out hides where the wait went.
  const auto start = std::chrono::steady_clock::now();
  if (o.forcing_model.empty() && warnings_shown())
    std::cerr << "no --forcing given: the catalog's default forcing model (fitted once, then kept in the user cache)\n";
  const auto inputs = load_prediction_inputs(o.inputs, o.forcing_model, std::nullopt, design_progress());
  const auto& catalog = inputs->catalog;
  const auto& threshold = *inputs->threshold;
  const design::PredictedTool tool =
      design::predict_tool(inputs->setup, point, o.surface, own ? &*own : nullptr);
  std::cout << fmt::format("{} on {}: design '{}' (first mode {:.1f} Hz), {}; {:.1f} s\n",
                           design::label(point), o.surface, tool.design_name, tool.first_mode_hz,
                           describe_descriptors(tool), seconds_since(start));
  if (tool.material_basis != "fitted")  // the numbers the FEM used are not yet a print's
    std::cout << fmt::format("its materials' constants: {} (the material table's basis)\n",
                             model::mechanics::describe_basis(tool.material_basis));

  nlohmann::json j = design::prediction_json(tool, threshold.source());

  if (const auto measured = measurement(o, catalog)) {
    const auto& [label, spectrum] = *measured;
    const auto& model = *inputs->setup.model;
    // Speeds to 0.5 mm/s: a recording's segmented speeds written in mm/s and read back.
    if (model::io::same_grid(spectrum, tool.spectrum, 5e-4)) {
      const auto c = design::compare_with_baselines(model, point, o.surface,
                                                    tool.response_magnitude, spectrum);
      nlohmann::json baselines = nlohmann::json::array();
      for (const auto& b : c.baselines)
        baselines.push_back({{"scalings_of", design::to_string(b.corner)},
                             {"rms_db", b.error.rms_db},
                             {"rms_db_by_speed", b.error.rms_db_by_speed}});
      j["comparison"] = {{"against", label},
                         {"rms_db", c.interpolated.rms_db},
                         {"rms_db_by_speed", c.interpolated.rms_db_by_speed},
                         {"no_interpolation_baselines", baselines},
                         {"beats_every_baseline", c.beats_every_baseline()}};
      std::cout << fmt::format("against {}: RMS {:.2f} dB over all bins and speeds\n", label,
                               c.interpolated.rms_db);
      std::cout << comparison_table(c, tool.spectrum.speeds_m_s);
      if (c.baselines.empty())
        std::cout << "a fitted design: nothing was interpolated, so there is no no-interpolation "
                     "baseline\n";
      else
        std::cout << fmt::format(
            "interpolation {} every no-interpolation baseline (Fig. 14: the same simulation with a "
            "fitted neighbour's tip and material scalings)\n",
            c.beats_every_baseline() ? "beats" : "does not beat");
    } else {
      std::cout << "against " << label
                << ": measured at other frequencies or speeds than the model's, so compared in "
                   "the plot only (each panel at the nearest measured speed)\n";
    }
    if (!o.plot.empty()) {
      ensure_folder(o.plot.parent_path());
      write_interpolation_figure(model, tool.point, tool.surface, tool.response_magnitude, label,
                                 spectrum, o.plot);
      say_wrote(o.plot);
    }
  }
  write_json_file(o.output, j);
  say_wrote(o.output);
}

}  // namespace

void add_predict_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global) {
  auto o = std::make_shared<PredictOptions>();
  auto* cmd = app.add_subcommand(
      "predict", "Predict the spectrum, friction and descriptors of a design on a surface");
  cmd->footer(
      "A design is a stylus file (design.json: a parametric stylus whose tip material is\n"
      "VeroClear-Piovarci2018, DM95 or DM85) or a point such as \"DM85:0.25,vero:0.75,tip=1mm\"\n"
      "(fractions adding up to 1; a tip between the fitted 1 and 4 mm: nothing is extrapolated).\n"
      "The output has the keys of `nibrig measure`: frequencies_hz, speeds_mm_s, amplitude_m_s2,\n"
      "descriptors, mu. Against a measurement (--measured, --against) it also reports, per speed,\n"
      "the RMS dB error of the prediction and of each no-interpolation baseline: the same\n"
      "simulation with the scalings of one fitted design around the point (Fig. 14's grey lines).");
  cmd->add_option("--design", o->design, "design.json, or a design point")->required();
  cmd->add_option("--surface", o->surface, "Surface id (office, note, stone, glass, ...)")
      ->required();
  cmd->add_option("--forcing", o->forcing_model,
                  "Forcing model from `nibrig forcing fit` (default: the catalog's, cached)");
  cmd->add_option("--catalog", o->inputs.catalog, "Tool catalog JSON (default: the bundled one)");
  cmd->add_option("--template", o->inputs.design_template,
                  "Stylus the design points are built on (default: "
                  "assets/designs/stylus_vero_tip2mm.json)");
  cmd->add_option("--materials", o->inputs.materials,
                  "Material table (default: assets/materials.json)");
  cmd->add_option("--modes", o->inputs.modes, "Modes of the design (default: the template's)")
      ->check(whole_in_range(1, 1000, "a number of modes"));
  cmd->add_option("--mesh-size", o->inputs.mesh_size, "Element size in metres")
      ->check(stylus_metres("an element size"));
  cmd->add_option("-o,--output", o->output, "Prediction JSON to write")
      ->capture_default_str()
      ->check(file_to_write());
  auto* measured = cmd->add_option("--measured", o->measured,
                                   "A `nibrig measure` JSON of a real recording to compare with");
  cmd->add_option("--against", o->against, "A catalog tool measured on the surface to compare with")
      ->excludes(measured);
  cmd->add_option("--plot", o->plot,
                  "PNG like Fig. 14: measurement, prediction and no-interpolation baselines, a "
                  "panel per speed (needs --measured or --against)")
      ->check(file_to_write());
  cmd->callback([o, global] {
    configure_logging(global->verbosity);
    // Refused before the work: checked after it, the whole prediction was printed and then nothing
    // written.
    if (!o->plot.empty() && o->measured.empty() && o->against.empty())
      throw CLI::ValidationError("--plot", "draws the prediction against a measurement: give "
                                           "--measured FILE or --against TOOL");
    run_predict(*o);
  });
}

}  // namespace nibrig::ui::cli
