#include "ui/cli/prediction_inputs.hpp"

#include <spdlog/spdlog.h>

#include "model/forcing/forcing_file.hpp"
#include "model/mechanics/material_table.hpp"
#include "model/mechanics/stylus_description.hpp"
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
    in->model = fit_forcing_for_prediction(load_forcing_inputs(options)).model;
  }
  in->threshold = model::measure::ThresholdCurve::load(default_threshold_curve());
  if (in->model.held_out_descriptor_errors.empty()) {
    spdlog::warn(
        "the forcing model has no held-out descriptor errors (a file written before they "
        "existed): predicted tools are placed as if their descriptors were measured, too "
        "confidently; `nibrig forcing fit` writes them");
  } else {
    if (in->model.descriptor_error_threshold != in->threshold->source())
      spdlog::warn(
          "the forcing model's descriptor errors were weighted by '{}', predictions by '{}'",
          in->model.descriptor_error_threshold, in->threshold->source());
    in->descriptor_errors = model::design::descriptor_error_covariance(
        in->model.held_out_descriptor_errors,
        model::design::friction_interpolation_errors(in->catalog));
    if (in->descriptor_errors->friction_samples == 0)
      spdlog::warn(
          "{} has no printed tool between two others of its material on a surface: the "
          "interpolated friction of predicted tools is taken as exact",
          in->catalog_file.string());
  }
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
  if (in->descriptor_errors) setup.descriptor_errors = &*in->descriptor_errors;
  setup.mesh_size = options.mesh_size;
  setup.modes = options.modes;
  return in;
}

}  // namespace nibrig::ui::cli
