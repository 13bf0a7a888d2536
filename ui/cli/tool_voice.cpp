#include "ui/cli/tool_voice.hpp"

#include <spdlog/spdlog.h>

#include <stdexcept>

#include "model/design/design_point.hpp"
#include "model/mechanics/design_model.hpp"
#include "model/mechanics/material_table.hpp"
#include "model/mechanics/stylus_description.hpp"
#include "rt/voice_builder.hpp"
#include "ui/cli/assets.hpp"
#include "ui/cli/prediction_inputs.hpp"

namespace nibrig::ui::cli {

StylusModes stylus_modes(const std::filesystem::path& design) {
  namespace mech = model::mechanics;
  const auto materials = mech::read_material_table(asset("materials.json"));
  const auto file = design.empty() ? asset(kDefaultVoiceDesign) : design;
  const mech::Design d = mech::read_design(file, materials);
  const mech::DesignModel model = mech::build_design_model(d, materials);
  spdlog::info("{}: {} modes, first at {:.1f} Hz (meshing and modes {:.2f} s)", d.name,
               model.modal.size(), model.modal.omega.front() / (2 * 3.141592653589793),
               model.seconds.meshing_s + model.seconds.assembly_s + model.seconds.modes_s);
  return {d.name, model.modal};
}

model::io::Catalog voice_catalog(const std::filesystem::path& catalog) {
  return model::io::read_catalog(catalog.empty() ? asset("default_catalog.json") : catalog);
}

const model::io::VelocitySpectrum& pairing_spectrum(const model::io::Catalog& catalog,
                                                    const std::filesystem::path& catalog_file,
                                                    const std::string& tool,
                                                    const std::string& surface) {
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

std::unique_ptr<rt::Voice> tool_voice(const model::io::Catalog& catalog,
                                      const std::filesystem::path& catalog_file,
                                      const std::string& tool, const std::string& surface,
                                      const StylusModes& stylus, double internal_rate,
                                      std::uint64_t seed) {
  return rt::build_voice(tool + " on " + surface, stylus.modal,
                         pairing_spectrum(catalog, catalog_file, tool, surface), internal_rate,
                         seed);
}

bool names_design_point(const std::string& tool) {
  return tool.find("tip=") != std::string::npos;
}

struct DesignPredictor::State {
  ForcingInputOptions options;
  std::filesystem::path forcing_file;
  std::unique_ptr<PredictionInputs> inputs;  // loaded when the first design point needs them
};

DesignPredictor::DesignPredictor(std::filesystem::path catalog_file,
                                 std::filesystem::path forcing_model)
    : state_(new State{{}, std::move(forcing_model), nullptr}) {
  state_->options.catalog = std::move(catalog_file);
  state_->options.design_template = asset(kDefaultVoiceDesign);
}

DesignPredictor::~DesignPredictor() = default;

model::design::PredictedTool DesignPredictor::predict(const std::string& point,
                                                      const std::string& surface) {
  const model::design::DesignPoint design = model::design::parse_design_point(point);
  if (!state_->inputs) state_->inputs = load_prediction_inputs(state_->options, state_->forcing_file);
  return model::design::predict_tool(state_->inputs->setup, design, surface);
}

std::unique_ptr<rt::Voice> predicted_voice(const model::design::PredictedTool& tool,
                                           double internal_rate, std::uint64_t seed) {
  return rt::build_voice("predicted " + model::design::label(tool.point) + " on " +
                             tool.surface,
                         tool.modal, tool.spectrum, internal_rate, seed);
}

}  // namespace nibrig::ui::cli
