// What predicting a design needs, read from files once: the catalog (for μ), the forcing model
// (a forcing file, or the default model of these inputs: model/design/default_forcing.hpp), the
// materials, the printed tools' template and the detection threshold.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>

#include "model/design/predicted_tool.hpp"
#include "model/forcing/forcing_inputs.hpp"
#include "model/forcing/forcing_model.hpp"
#include "model/io/catalog_file.hpp"
#include "model/measure/threshold_curve.hpp"

namespace nibrig::model::design {

struct PredictionInputs {
  std::filesystem::path catalog_file;
  // The files setup's template and materials were read from: a cached result that depends on them
  // (the design-response grid) is keyed by their content.
  std::filesystem::path design_template_file, materials_file;
  io::Catalog catalog;
  forcing::ForcingModel model;
  std::optional<measure::ThresholdCurve> threshold;
  // From the model's held-out errors and the catalog's middle tips; none for a model without them.
  std::optional<DescriptorErrorCovariance> descriptor_errors;
  PredictionSetup setup;  // points into this object, which therefore stays put
};

// `options` names the catalog, template, materials and the designs' modes and mesh size (empty or
// 0: the bundled ones and the template's); `forcing_file` the model, a file or the name of one a lab
// stored (forcing_store.hpp) (empty: the default model
// fitted to the catalog at the same modes and mesh size, read from the user cache or fitted and
// kept there, with `progress` as its designs are simulated); `fitted`, when given, is used instead.
// A model without held-out descriptor errors (a file from before them) is used with a warning: its
// predictions are placed as if their descriptors were measured.
std::unique_ptr<PredictionInputs> load_prediction_inputs(
    const forcing::ForcingInputOptions& options, const std::filesystem::path& forcing_file,
    std::optional<forcing::ForcingModel> fitted = std::nullopt,
    const forcing::DesignProgress& progress = {});

}  // namespace nibrig::model::design
