// What predicting a design needs, read from files once: the catalog (for μ), the forcing model
// (from `nibrig forcing fit`, or fitted to the catalog when none is given), the materials, the
// printed tools' template and the detection threshold. Shared by predict, design, the voices of
// render and audition, and the demo.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>

#include "model/design/predicted_tool.hpp"
#include "model/forcing/forcing_model.hpp"
#include "model/io/catalog_file.hpp"
#include "model/measure/threshold_curve.hpp"
#include "ui/cli/forcing_inputs.hpp"

namespace nibrig::ui::cli {

struct PredictionInputs {
  std::filesystem::path catalog_file;
  model::io::Catalog catalog;
  model::forcing::ForcingModel model;
  std::optional<model::measure::ThresholdCurve> threshold;
  // From the model's held-out errors and the catalog's middle tips; none for a model without them.
  std::optional<model::design::DescriptorErrorCovariance> descriptor_errors;
  model::design::PredictionSetup setup;  // points into this object, which therefore stays put
};

// `options` names the catalog, template, materials and the designs' modes and mesh size (empty or
// 0: the bundled ones and the template's); `forcing_file` the model (empty: fit the catalog now,
// ~8 s, said in the log); `fitted`, when given, is used as the model instead. A model without
// held-out descriptor errors (a file from before them) is used with a warning: its predictions are
// placed as if their descriptors were measured.
std::unique_ptr<PredictionInputs> load_prediction_inputs(
    const ForcingInputOptions& options, const std::filesystem::path& forcing_file,
    std::optional<model::forcing::ForcingModel> fitted = std::nullopt);

}  // namespace nibrig::ui::cli
