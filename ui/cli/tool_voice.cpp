#include "ui/cli/tool_voice.hpp"

#include <spdlog/spdlog.h>

#include <stdexcept>

#include "model/design/design_point.hpp"
#include "model/forcing/forcing_file.hpp"
#include "model/forcing/forcing_fit.hpp"
#include "model/mechanics/design.hpp"
#include "model/mechanics/design_model.hpp"
#include "model/mechanics/material_table.hpp"
#include "rt/voice_builder.hpp"
#include "ui/cli/assets.hpp"
#include "ui/cli/forcing_inputs.hpp"

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
  const model::io::Catalog& catalog;
  std::filesystem::path catalog_file, forcing_file;
  std::optional<model::forcing::ForcingModel> model;
  std::optional<model::measure::ThresholdCurve> threshold;
  model::design::PredictionSetup setup;
};

DesignPredictor::DesignPredictor(const model::io::Catalog& catalog,
                                 std::filesystem::path catalog_file,
                                 std::filesystem::path forcing_model)
    : state_(new State{catalog, std::move(catalog_file), std::move(forcing_model), {}, {}, {}}) {}

DesignPredictor::~DesignPredictor() = default;

model::design::PredictedTool DesignPredictor::predict(const std::string& point,
                                                      const std::string& surface) {
  const model::design::DesignPoint design = model::design::parse_design_point(point);
  State& s = *state_;
  if (!s.model) {
    if (!s.forcing_file.empty()) {
      s.model = model::forcing::read_forcing_model(s.forcing_file);
    } else {
      spdlog::info("{}: no --forcing given, fitting the forcing model to the catalog first", point);
      ForcingInputOptions inputs;
      inputs.catalog = s.catalog_file;
      s.model = model::forcing::fit_forcing_model(load_forcing_inputs(inputs).exemplars);
    }
    s.threshold = model::measure::ThresholdCurve::load(asset("thresholds/israr2006_pen_hold.csv"));
    s.setup.model = &*s.model;
    s.setup.catalog = &s.catalog;
    s.setup.materials = model::mechanics::read_material_table(asset("materials.json"));
    s.setup.template_design =
        model::mechanics::read_design(asset(kDefaultVoiceDesign), s.setup.materials);
    s.setup.threshold = &*s.threshold;
  }
  return model::design::predict_tool(s.setup, design, surface);
}

std::unique_ptr<rt::Voice> predicted_voice(const model::design::PredictedTool& tool,
                                           double internal_rate, std::uint64_t seed) {
  return rt::build_voice("predicted " + model::design::to_string(tool.point) + " on " +
                             tool.surface,
                         tool.modal, tool.spectrum, internal_rate, seed);
}

}  // namespace nibrig::ui::cli
