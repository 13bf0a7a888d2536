#include "model/design/tool_sound.hpp"

#include <algorithm>
#include <stdexcept>

#include "model/catalog/tool_names.hpp"
#include "model/design/design_point.hpp"
#include "model/design/prediction_inputs.hpp"
#include "model/design/stylus_modes.hpp"
#include "model/io/bundled_assets.hpp"
#include "model/io/user_cache.hpp"

namespace nibrig::model::design {

bool names_design_point(const std::string& tool) { return tool.find("tip=") != std::string::npos; }

std::optional<DesignPoint> unmeasured_print(const io::Catalog& catalog, const std::string& tool) {
  if (std::any_of(catalog.tools.begin(), catalog.tools.end(),
                  [&](const io::ToolEntry& t) { return t.id == tool; }))
    return std::nullopt;
  const io::ToolEntry entry = catalog::describe_tool(tool);
  if (entry.kind != "printed" || !entry.tip_diameter_m) return std::nullopt;
  return DesignPoint{{{catalog_material_name(entry.material), 1.0}}, *entry.tip_diameter_m};
}

const io::VelocitySpectrum& pairing_spectrum(const io::Catalog& catalog,
                                             const std::filesystem::path& catalog_file,
                                             const std::string& tool, const std::string& surface) {
  const std::string where = catalog_file.empty() ? "the bundled catalog" : catalog_file.string();
  std::string surfaces;
  for (const auto& p : catalog.pairings) {
    if (p.tool != tool || !p.vibration) continue;
    if (p.surface == surface) return p.vibration->spectrum;
    surfaces += (surfaces.empty() ? "" : ", ") + p.surface;
  }
  if (!surfaces.empty())
    throw std::invalid_argument(where + " has no vibration spectrum of '" + tool + "' on '" +
                                surface + "'; it has one on: " + surfaces);
  std::string tools;
  for (const auto& t : catalog.tools) {
    bool has = false;
    for (const auto& p : catalog.pairings) has |= p.tool == t.id && p.vibration.has_value();
    if (has) tools += (tools.empty() ? "" : ", ") + t.id;
  }
  throw std::invalid_argument(where + " has no vibration spectrum of tool '" + tool +
                              "'; tools with one: " + tools);
}

struct ToolSounds::State {
  ToolSoundOptions options;
  io::Catalog catalog;
  std::optional<ToolSound> stylus;               // name and modes; on first need (cached)
  std::unique_ptr<PredictionInputs> prediction;  // loaded on the first design point
};

ToolSounds::ToolSounds(ToolSoundOptions options)
    : state_(new State{std::move(options), {}, {}, {}}) {
  state_->catalog = io::read_catalog(io::or_default(state_->options.catalog, io::default_catalog));
}

ToolSounds::~ToolSounds() = default;

const io::Catalog& ToolSounds::catalog() const { return state_->catalog; }

void ToolSounds::check(const std::string& tool, const std::string& surface) const {
  if (names_design_point(tool))
    parse_design_point(tool);
  else if (!unmeasured_print(state_->catalog, tool))
    pairing_spectrum(state_->catalog, state_->options.catalog, tool, surface);
}

const PredictionSetup& ToolSounds::prediction_setup() {
  if (!state_->prediction) {
    forcing::ForcingInputOptions options;
    options.catalog = state_->options.catalog;
    options.design_template = io::default_stylus_design();
    state_->prediction = load_prediction_inputs(options, state_->options.forcing_model,
                                                std::nullopt, state_->options.progress);
  }
  return state_->prediction->setup;
}

PredictedTool ToolSounds::predict(const std::string& point, const std::string& surface) {
  const DesignPoint design = parse_design_point(point);  // refuses a bad point before any work
  return predict_tool(prediction_setup(), design, surface);
}

// A print's sound is its modes driven by its predicted spectrum; its friction, which a print the
// catalog has not measured lacks, plays no part in it.
ToolSound ToolSounds::print_sound(const DesignPoint& point, const std::string& surface) {
  const PredictionSetup& setup = prediction_setup();
  SimulatedResponse response = simulate_response(setup, point);
  io::VelocitySpectrum spectrum =
      predict_spectrum(*setup.model, point, surface, response.response_magnitude);
  return {"predicted " + label(point) + " on " + surface, std::move(response.design_name),
          std::move(response.modal), std::move(spectrum)};
}

ToolSound predicted_sound(PredictedTool p) {
  return {"predicted " + label(p.point) + " on " + p.surface, p.design_name, std::move(p.modal),
          std::move(p.spectrum)};
}

bool ToolSounds::solves_stylus_modes() const {
  if (state_->stylus) return false;
  std::error_code error;
  const auto file = stylus_modes_file(state_->options.stylus_design);
  return !std::filesystem::exists(file, error) && io::shipped_twin(file).empty();  // nor shipped
}

ToolSound ToolSounds::sound(const std::string& tool, const std::string& surface) {
  if (names_design_point(tool)) return predicted_sound(predict(tool, surface));
  if (auto print = unmeasured_print(state_->catalog, tool)) return print_sound(*print, surface);
  const io::VelocitySpectrum& spectrum =
      pairing_spectrum(state_->catalog, state_->options.catalog, tool, surface);
  if (!state_->stylus) {
    StylusModes stylus = stylus_modes(state_->options.stylus_design).value;
    state_->stylus = ToolSound{"", std::move(stylus.design_name), std::move(stylus.modal), {}};
  }
  return {tool + " on " + surface, state_->stylus->modes, state_->stylus->modal, spectrum};
}

}  // namespace nibrig::model::design
