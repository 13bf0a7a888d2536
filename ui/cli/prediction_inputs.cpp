#include "ui/cli/prediction_inputs.hpp"

#include <spdlog/spdlog.h>

#include "model/forcing/forcing_file.hpp"
#include "model/forcing/forcing_fit.hpp"
#include "model/mechanics/design.hpp"
#include "model/mechanics/material_table.hpp"
#include "ui/cli/assets.hpp"

namespace nibrig::ui::cli {

std::unique_ptr<PredictionInputs> load_prediction_inputs(
    const ForcingInputOptions& options, const std::filesystem::path& forcing_file,
    std::optional<model::forcing::ForcingModel> fitted) {
  auto in = std::make_unique<PredictionInputs>();
  in->catalog_file = options.catalog.empty() ? asset("default_catalog.json") : options.catalog;
  in->catalog = model::io::read_catalog(in->catalog_file);
  if (fitted) {
    in->model = std::move(*fitted);
  } else if (!forcing_file.empty()) {
    in->model = model::forcing::read_forcing_model(forcing_file);
  } else {
    spdlog::info("no --forcing given: fitting the forcing model to the catalog first");
    in->model = model::forcing::fit_forcing_model(load_forcing_inputs(options).exemplars);
  }
  in->threshold = model::measure::ThresholdCurve::load(asset("thresholds/israr2006_pen_hold.csv"));
  auto& setup = in->setup;
  setup.materials = model::mechanics::read_material_table(
      options.materials.empty() ? asset("materials.json") : options.materials);
  setup.template_design = model::mechanics::read_design(
      options.design_template.empty() ? asset("designs/stylus_vero_tip2mm.json")
                                      : options.design_template,
      setup.materials);
  setup.model = &in->model;
  setup.catalog = &in->catalog;
  setup.threshold = &*in->threshold;
  setup.mesh_size = options.mesh_size;
  setup.modes = options.modes;
  return in;
}

}  // namespace nibrig::ui::cli
