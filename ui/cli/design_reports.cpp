#include "ui/cli/design_reports.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "model/io/catalog.hpp"
#include "model/io/format_error.hpp"
#include "model/io/json_fields.hpp"
#include "ui/cli/space_figures.hpp"

namespace nibrig::ui::cli {

namespace design = model::design;

nlohmann::json prediction_json(const design::PredictedTool& tool,
                               const std::string& threshold_source) {
  nlohmann::json j = model::io::to_json(tool.spectrum);
  j["kind"] = "prediction";
  j["tool"] = design::to_string(tool.point);
  j["surface"] = tool.surface;
  j["mu"] = tool.mu;
  nlohmann::json bands = nlohmann::json::object();
  for (const auto& [k, energies] : tool.vibration.band_energies) bands[std::to_string(k)] = energies;
  j["descriptors"] = {{"weighted_mean", tool.vibration.weighted_mean},
                      {"weighted_power", tool.vibration.weighted_power},
                      {"band_energies", bands}};
  j["threshold_curve"] = threshold_source;
  j["design"] = {{"name", tool.design_name},
                 {"first_mode_hz", tool.first_mode_hz},
                 {"tip_diameter_mm", tool.point.tip_diameter_m * 1e3}};
  for (const auto& share : tool.point.mix) j["design"]["mix"][share.material] = share.fraction;
  j["notes"] = {
      "amplitude = |H| (simulated design) x F_S (fitted surface forcing) x t x m (tip and "
      "material scaling interpolated linearly, Sec. 5.3); mu interpolated linearly between "
      "measured printed tools (model/design/predicted_tool.hpp)"};
  return j;
}

std::pair<model::io::ToolEntry, model::io::Pairing> read_prediction(
    const std::filesystem::path& file, const model::measure::ThresholdCurve& threshold) {
  namespace fields = model::io::json_fields;
  const nlohmann::json j = fields::parse_file(file);
  fields::as_object(j, file, "");
  if (fields::string_member(j, "kind", file, "") != "prediction")
    throw model::io::FormatError(file, fields::place("kind"),
                                 "expected \"prediction\" (a `nibrig predict` file)");
  design::PredictedTool tool;
  try {
    tool.point = design::parse_design_point(fields::string_member(j, "tool", file, ""));
  } catch (const std::invalid_argument& e) {
    throw model::io::FormatError(file, fields::place("tool"), e.what());
  }
  tool.surface = fields::string_member(j, "surface", file, "");
  tool.mu = fields::number_member(j, "mu", file, "");
  tool.spectrum = model::io::velocity_spectrum_from_json(j, file, "");
  tool.vibration = model::measure::compute_vibration_descriptors(tool.spectrum, threshold);
  if (j.contains("design") && j["design"].is_object() && j["design"].contains("name"))
    tool.design_name = fields::string_member(j["design"], "name", file, "design");
  return {design::predicted_tool_entry(tool), design::predicted_pairing(tool, threshold.source())};
}

nlohmann::json candidate_json(const design::Candidate& c) {
  return {{"design", design::to_string(c.point)},
          {"distance", c.distance},
          {"distance_sd", c.distance_sd},
          {"mu", c.mu},
          {"weighted_mean", c.weighted_mean},
          {"coordinates", std::vector<double>(c.placement.mean.data(),
                                              c.placement.mean.data() + c.placement.mean.size())}};
}

nlohmann::json search_json(const design::SearchResult& result, const std::string& target,
                           const std::string& surface, const std::string& how, double seconds,
                           int runners_up) {
  nlohmann::json j;
  j["kind"] = "design_search";
  j["target"] = target;
  j["surface"] = surface;
  j["search"] = how;
  j["seconds"] = seconds;
  j["optimum"] = candidate_json(result.best());
  j["runners_up"] = nlohmann::json::array();
  for (std::size_t k : result.runners_up(static_cast<std::size_t>(runners_up)))
    j["runners_up"].push_back(candidate_json(result.evaluated[k]));
  j["path"] = nlohmann::json::array();
  for (const auto& c : result.evaluated) j["path"].push_back(candidate_json(c));
  return j;
}

void write_search_plot(const model::space::SpaceFile& space, const std::string& target,
                       const model::space::Placement* placed_target,
                       const design::SearchResult& result, const std::vector<std::size_t>& ends,
                       const std::string& surface, const std::filesystem::path& png) {
  std::vector<PlacedTool> placed;
  if (placed_target != nullptr) placed.push_back({target, *placed_target, "target", true});
  for (std::size_t k = 0; k < result.evaluated.size(); ++k) {
    if (k == result.ranked.front()) continue;
    const auto& c = result.evaluated[k];
    const bool end = std::find(ends.begin(), ends.end(), k) != ends.end();
    placed.push_back({end ? design::label(c.point) : "", c.placement,
                      end ? "the designs searched between" : "candidates", end});
  }
  const auto& best = result.best();
  placed.push_back({"optimum " + design::label(best.point), best.placement, "optimum", true});
  write_space_plot(space, placed, fmt::format("Designs on {} nearest {}", surface, target), png);
}

}  // namespace nibrig::ui::cli
