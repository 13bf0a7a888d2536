#include "model/design/prediction_inputs.hpp"

#include <spdlog/spdlog.h>

#include "model/design/default_forcing.hpp"
#include "model/forcing/forcing_file.hpp"
#include "model/forcing/forcing_store.hpp"
#include "model/io/bundled_assets.hpp"
#include "model/mechanics/material_table.hpp"
#include "model/mechanics/stylus_description.hpp"

namespace nibrig::model::design {

std::unique_ptr<PredictionInputs> load_prediction_inputs(
    const forcing::ForcingInputOptions& options, const std::filesystem::path& forcing_file,
    std::optional<forcing::ForcingModel> fitted, const forcing::DesignProgress& progress) {
  forcing::check_forcing_input_options(options);  // before the catalog is read or a mesh made
  auto in = std::make_unique<PredictionInputs>();
  in->catalog_file = io::or_default(options.catalog, io::default_catalog);
  in->catalog = io::read_catalog(in->catalog_file);
  if (fitted) {
    in->model = std::move(*fitted);
  } else if (!forcing_file.empty()) {
    // A file, or a model a lab calibrated and stored by name (forcing_store.hpp).
    in->model = forcing::read_forcing_model(forcing::find_forcing_model(forcing_file.string()));
  } else {
    DefaultsOptions defaults;
    defaults.catalog = options.catalog;
    defaults.stylus_design = options.design_template;
    defaults.materials = options.materials;
    const ForcingResolution resolution{options.modes, options.mesh_size};
    Cached<forcing::ForcingModel> model = default_forcing_model(defaults, resolution, progress);
    spdlog::info("no forcing model given: the catalog's default one, {} {}",
                 model.computed ? "fitted now and kept in" : "read from", model.file.string());
    in->model = std::move(model.value);
  }
  in->threshold = measure::ThresholdCurve::load(io::default_threshold_curve());
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
    in->descriptor_errors = descriptor_error_covariance(
        in->model.held_out_descriptor_errors,
        friction_interpolation_errors(in->catalog));
    if (in->descriptor_errors->friction_samples == 0)
      spdlog::warn(
          "{} has no printed tool between two others of its material on a surface: the "
          "interpolated friction of predicted tools is taken as exact",
          in->catalog_file.string());
  }
  auto& setup = in->setup;
  in->materials_file = io::or_default(options.materials, io::default_materials);
  in->design_template_file = io::or_default(options.design_template, io::default_stylus_design);
  setup.materials = mechanics::read_material_table(in->materials_file);
  setup.template_design = mechanics::read_design(in->design_template_file, setup.materials);
  setup.model = &in->model;
  setup.catalog = &in->catalog;
  setup.threshold = &*in->threshold;
  if (in->descriptor_errors) setup.descriptor_errors = &*in->descriptor_errors;
  setup.mesh_size = options.mesh_size;
  setup.modes = options.modes;
  return in;
}

}  // namespace nibrig::model::design
