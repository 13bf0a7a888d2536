// The prediction file (`nibrig predict` output, FORMATS.md "Prediction"): a predicted design as the
// keys `nibrig measure` writes for a recording, so the two compare directly, with the design and
// the error of its descriptors. Every face that saves or opens a design reads and writes it here.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "model/design/design_point.hpp"
#include "model/design/predicted_tool.hpp"
#include "model/io/catalog_file.hpp"
#include "model/measure/threshold_curve.hpp"

namespace nibrig::model::design {

// kind "prediction": tool (the design point), surface, frequencies_hz, speeds_mm_s,
// amplitude_m_s2, descriptors (weighted_mean, weighted_power, band_energies), mu,
// threshold_curve, design (name, first_mode_hz, tip_diameter_mm, mix), notes, and when the tool
// has one, descriptor_error_covariance {names (every descriptor a space may use), matrix,
// vibration_samples, friction_samples}: the error of its descriptors, for placing it.
nlohmann::json prediction_json(const PredictedTool& tool, const std::string& threshold_source);

// A prediction JSON read back as the catalog entries of a predicted tool (kind "predicted", id
// "pred:<design>"), its vibration descriptors recomputed from its spectrum with `threshold`, and
// its descriptor error (empty when the file has none). Every field prediction_json writes is checked
// to its type and range, read or not (descriptors, design, notes, a comparison): throws
// io::FormatError naming the file and field (not a prediction, a missing field, a string for a
// number, null, 1e300, a μ beyond 10, a design whose tip or mix differs from its tool, a covariance
// that is not square over its names, not symmetric or with a negative variance).
struct ReadPrediction {
  DesignPoint point;    // the design predicted
  std::string surface;  // on which surface
  io::ToolEntry tool;
  io::Pairing pairing;
  DescriptorErrorCovariance descriptor_errors;
};
ReadPrediction read_prediction(const std::filesystem::path& file,
                               const measure::ThresholdCurve& threshold);

// Only the design a prediction file predicted and on which surface, with the same refusals (what
// `export` takes: a damaged file is refused there too).
struct PredictedDesign {
  DesignPoint point;
  std::string surface;
};
PredictedDesign read_predicted_design(const std::filesystem::path& file);

}  // namespace nibrig::model::design
