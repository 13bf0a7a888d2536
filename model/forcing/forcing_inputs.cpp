#include "model/forcing/forcing_inputs.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cfloat>
#include <chrono>
#include <set>
#include <sstream>
#include <stdexcept>

#include "model/forcing/forcing_fit.hpp"
#include "model/forcing/leave_one_out.hpp"
#include "model/io/bundled_assets.hpp"
#include "model/io/catalog_file.hpp"
#include "model/io/velocity_spectrum.hpp"
#include "model/measure/threshold_curve.hpp"
#include "model/mechanics/material_table.hpp"

namespace nibrig::model::forcing {

namespace mech = mechanics;

void check_forcing_input_options(const ForcingInputOptions& o) {
  if (o.modes < 0 || o.modes > kMostModes)
    throw std::invalid_argument("modes: " + std::to_string(o.modes) +
                                ": expected 0 (the template's) or 1 to " +
                                std::to_string(kMostModes));
  // A size below DBL_MIN is no size: it would mesh without end.
  if (!(o.mesh_size == 0.0 || (o.mesh_size >= DBL_MIN && o.mesh_size <= kLargestMeshSizeM))) {
    std::ostringstream message;
    message << "mesh_size: " << o.mesh_size
            << ": expected 0 (the template's) or an element size in metres, > 0 and at "
            << "most " << kLargestMeshSizeM
            << " (a stylus is centimetres long: millimetres given as metres?)";
    throw std::invalid_argument(message.str());
  }
}

ForcingInputs load_forcing_inputs(const ForcingInputOptions& o, const DesignProgress& progress) {
  check_forcing_input_options(o);
  const auto catalog_path = io::or_default(o.catalog, io::default_catalog);
  const auto template_path = io::or_default(o.design_template, io::default_stylus_design);
  const auto materials_path = io::or_default(o.materials, io::default_materials);

  for (const auto& [path, what] : {std::pair{catalog_path, "a tool catalog JSON"},
                                   std::pair{template_path, "a stylus design JSON"},
                                   std::pair{materials_path, "a material table JSON"}})
    if (!std::filesystem::exists(path))
      throw std::runtime_error(path.string() + ": no such file (expected " + what + ")");
  const io::Catalog catalog = io::read_catalog(catalog_path);
  const mech::MaterialTable materials = mech::read_material_table(materials_path);
  ForcingInputs inputs;
  inputs.selection = select_printed_exemplars(catalog, &materials);
  inputs.exemplars = std::move(inputs.selection.exemplars);
  inputs.selection.exemplars.clear();
  for (const auto& excluded : inputs.selection.excluded) spdlog::info("left out: {}", excluded);
  if (!o.frequencies_hz.empty()) {
    std::size_t resampled = 0;
    for (auto& e : inputs.exemplars) {
      if (e.measured.frequencies_hz == o.frequencies_hz) continue;
      try {
        e.measured = io::spectrum_at_frequencies(e.measured, o.frequencies_hz);
      } catch (const std::invalid_argument& error) {
        throw std::invalid_argument(catalog_path.string() + ": " + e.tool + " on " + e.surface +
                                    ": " + error.what() + " (the model's grid)");
      }
      ++resampled;
    }
    if (resampled > 0)
      inputs.notes.push_back(
          fmt::format("{} spectra interpolated linearly onto the model's {} frequencies", resampled,
                      o.frequencies_hz.size()));
  }
  if (inputs.exemplars.empty())
    throw std::runtime_error(catalog_path.string() +
                             ": no printed tool with a material, a tip diameter and a vibration "
                             "spectrum: nothing to fit");

  const mech::Design template_design = mech::read_design(template_path, materials);
  ResponseOptions response_options;
  response_options.modes = o.modes;
  response_options.mesh_size = o.mesh_size;
  const auto start = std::chrono::steady_clock::now();
  inputs.designs =
      attach_responses(inputs.exemplars, template_design, materials, response_options,
                       [&](const DesignResponse& r, std::size_t done, std::size_t total) {
                         spdlog::info("{}: {} modes, first at {:.1f} Hz, {:.2f} s", r.design,
                                      r.modes, r.first_mode_hz, r.seconds);
                         if (progress) progress(r, done, total);
                       });
  inputs.response_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const int modes = o.modes > 0 ? o.modes : template_design.modes;
  const double mesh = o.mesh_size > 0 ? o.mesh_size : template_design.mesh_size;
  inputs.notes.push_back("catalog: " + catalog_path.string());
  inputs.notes.push_back(fmt::format(
      "responses |H| from tip force to sensor acceleration of each tool's design: template {} "
      "('{}') with the tool's tip diameter and tip insert (model/forcing/printed_tool_design.hpp), "
      "materials {}, {} modes, {:.2f} mm quadratic tetrahedra",
      template_path.string(), template_design.name, materials_path.string(), modes, mesh * 1e3));
  const auto missing = missing_paper_tools(inputs.exemplars);
  if (!missing.empty()) {
    std::string list;
    for (const auto& m : missing) list += (list.empty() ? "" : ", ") + m;
    inputs.notes.push_back("of the paper's 27 tools this catalog lacks: " + list);
  }
  return inputs;
}

ForcingForPrediction fit_forcing_for_prediction(const ForcingInputs& inputs) {
  ForcingModel model = fit_forcing_model(inputs.exemplars);
  model.notes = inputs.notes;
  model.notes.push_back(
      "fit of Eq. 10 in log amplitude; ln t(2 mm) = ln m(vero) = 0 fix the scale, so F_S is the "
      "forcing the 2 mm VeroClear tool sees (model/forcing/forcing_fit.hpp)");
  const auto threshold = measure::ThresholdCurve::load(io::default_threshold_curve());
  LeaveOneOut held_out = leave_every_one_out(inputs.exemplars, &threshold);
  model.held_out_descriptor_errors = descriptor_errors(held_out);
  model.descriptor_error_threshold = threshold.source();
  model.notes.push_back(fmt::format(
      "held_out_descriptor_errors: {} of {} exemplars held out of the fit in turn and predicted; "
      "log10(predicted/measured) of their weighted descriptors, the error a predicted tool's "
      "placement carries (model/design/descriptor_uncertainty.hpp)",
      model.held_out_descriptor_errors.size(), inputs.exemplars.size()));
  return {std::move(model), std::move(held_out)};
}

std::string describe_inputs(const ForcingInputs& inputs) {
  std::set<std::string> surfaces;
  std::size_t paper = 0;
  for (const auto& e : inputs.exemplars) {
    surfaces.insert(e.surface);
    paper += is_paper_tool(e) ? 1 : 0;
  }
  std::string out =
      fmt::format("{} exemplars of printed tools on {} surfaces; {} of the paper's 27 tools\n",
                  inputs.exemplars.size(), surfaces.size(), paper);
  const auto missing = missing_paper_tools(inputs.exemplars);
  if (!missing.empty()) {
    std::string list;
    for (const auto& m : missing) list += (list.empty() ? "" : ", ") + m;
    out += "missing from the catalog: " + list + "\n";
  }
  out += fmt::format(
      "left out: {} pairings of printed tools without a design or spectrum (-v lists them), {} "
      "of real and commercial tools\n",
      inputs.selection.excluded.size(), inputs.selection.other_kinds);
  double low = 1e300, high = 0;
  for (const auto& d : inputs.designs) {
    low = std::min(low, d.first_mode_hz);
    high = std::max(high, d.first_mode_hz);
  }
  out +=
      fmt::format("simulated {} designs in {:.1f} s ({} modes each, first mode {:.1f}-{:.1f} Hz)\n",
                  inputs.designs.size(), inputs.response_seconds,
                  inputs.designs.empty() ? 0 : inputs.designs.front().modes, low, high);
  return out;
}

}  // namespace nibrig::model::forcing
