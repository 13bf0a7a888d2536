// What `nibrig predict`, `nibrig design` and the demo write about predicted designs: the
// prediction JSON (the keys `nibrig measure` writes for a recording, so the two compare directly),
// the search JSON, and the search's path in the space (Fig. 17).
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "model/design/design_search.hpp"
#include "model/design/predicted_tool.hpp"
#include "model/io/catalog_file.hpp"
#include "model/measure/threshold_curve.hpp"
#include "model/space/space_file.hpp"

namespace nibrig::ui::cli {

// kind "prediction": tool (the design point), surface, frequencies_hz, speeds_mm_s,
// amplitude_m_s2, descriptors (weighted_mean, weighted_power, band_energies), mu,
// threshold_curve, design (name, first_mode_hz, tip_diameter_mm, mix), notes, and when the tool
// has one, descriptor_error_covariance {names (every descriptor a space may use), matrix,
// vibration_samples, friction_samples}: the error of its descriptors, for placing it.
nlohmann::json prediction_json(const model::design::PredictedTool& tool,
                               const std::string& threshold_source);

// "mu 0.273 ± 0.0087, weighted mean vibration 0.07339 ± 12.8 %": the predicted descriptors with
// their cross-validated error (± one standard deviation; none printed when the tool has none, a
// measured μ having no interpolation error).
std::string describe_descriptors(const model::design::PredictedTool& tool);

// A prediction JSON read back as the catalog entries of a predicted tool (kind "predicted", id
// "pred:<design>"), its vibration descriptors recomputed from its spectrum with `threshold`, and
// its descriptor error (empty when the file has none). Throws io::FormatError naming the file and
// field (not a prediction, a missing or bad field, a covariance that is not square over its names,
// not symmetric or with a negative variance).
struct ReadPrediction {
  model::io::ToolEntry tool;
  model::io::Pairing pairing;
  model::design::DescriptorErrorCovariance descriptor_errors;
};
ReadPrediction read_prediction(const std::filesystem::path& file,
                               const model::measure::ThresholdCurve& threshold);

// One candidate: design, distance, distance_sd, mu, weighted_mean, coordinates.
nlohmann::json candidate_json(const model::design::Candidate& candidate);

// kind "design_search": target, surface, search (how), seconds, optimum, runners_up (distinct
// designs, SearchResult::runners_up), path (every candidate in the order evaluated).
nlohmann::json search_json(const model::design::SearchResult& result, const std::string& target,
                           const std::string& surface, const std::string& how, double seconds,
                           int runners_up);

// The space's judged stimuli, the target when it was placed rather than judged, every candidate
// (the path; `ends` of them labelled, e.g. the two designs of a line search) and the optimum with
// its 68 % / 95 % ellipses.
void write_search_plot(const model::space::SpaceFile& space, const std::string& target,
                       const model::space::Placement* placed_target,
                       const model::design::SearchResult& result,
                       const std::vector<std::size_t>& ends, const std::string& surface,
                       const std::filesystem::path& png);

}  // namespace nibrig::ui::cli
