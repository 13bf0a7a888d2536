#include "ui/cli/design_reports.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "model/forcing/descriptor_error.hpp"
#include "model/io/catalog_file.hpp"
#include "model/io/format_error.hpp"
#include "model/io/json_fields.hpp"
#include "model/space/catalog_descriptors.hpp"
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
  for (const auto& [k, energies] : tool.vibration.band_energies)
    bands[std::to_string(k)] = energies;
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
  if (!tool.descriptor_errors.empty()) {
    const auto& e = tool.descriptor_errors;
    nlohmann::json matrix = nlohmann::json::array();
    for (Eigen::Index i = 0; i < e.covariance.rows(); ++i) {
      const Eigen::VectorXd row = e.covariance.row(i).transpose();
      matrix.push_back(std::vector<double>(row.data(), row.data() + row.size()));
    }
    j["descriptor_error_covariance"] = {{"names", e.names},
                                        {"matrix", matrix},
                                        {"vibration_samples", e.vibration_samples},
                                        {"friction_samples", e.friction_samples}};
    j["notes"].push_back(
        "descriptor_error_covariance: second moments of the descriptors' errors when printed "
        "tools were predicted without their own data (model/design/descriptor_uncertainty.hpp); "
        "added, through the space's descriptor map, to where this tool is placed");
  }
  return j;
}

std::string describe_descriptors(const design::PredictedTool& tool) {
  std::string mu = fmt::format("mu {:.3f}", tool.mu);
  std::string vibration =
      fmt::format("weighted mean vibration {:.4g}", tool.vibration.weighted_mean);
  if (!tool.descriptor_errors.empty()) {
    const auto names = model::space::paper_descriptor_names(2);  // μ, log10 weighted mean
    const Eigen::MatrixXd c = tool.descriptor_errors.block(names);
    if (c(0, 0) > 0) mu += fmt::format(" ± {:.4f}", std::sqrt(c(0, 0)));
    vibration += fmt::format(" ± {:.1f} %", model::forcing::percent_off(std::sqrt(c(1, 1))));
  }
  return mu + ", " + vibration;
}

namespace {

design::DescriptorErrorCovariance read_descriptor_errors(const nlohmann::json& j,
                                                         const std::filesystem::path& file) {
  namespace fields = model::io::json_fields;
  const std::string key = "descriptor_error_covariance";
  const auto& section = fields::as_object(j[key], file, key);
  design::DescriptorErrorCovariance e;
  const std::string names_at = fields::member_path(key, "names");
  const auto& names = fields::as_array(fields::member(section, "names", file, key), file, names_at);
  for (std::size_t i = 0; i < names.size(); ++i)
    e.names.push_back(fields::as_string(names[i], file, fields::element_path(names_at, i)));
  const std::string matrix_at = fields::member_path(key, "matrix");
  const auto& rows =
      fields::as_array(fields::member(section, "matrix", file, key), file, matrix_at);
  const auto n = static_cast<Eigen::Index>(e.names.size());
  if (rows.size() != e.names.size())
    throw model::io::FormatError(file, fields::place(matrix_at),
                                 "expected one row per name (" + std::to_string(n) + ")");
  e.covariance.resize(n, n);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::string row_at = fields::element_path(matrix_at, i);
    const auto row = fields::as_number_array(rows[i], file, row_at);
    if (row.size() != e.names.size())
      throw model::io::FormatError(file, fields::place(row_at),
                                   "expected one value per name (" + std::to_string(n) + ")");
    for (std::size_t k = 0; k < row.size(); ++k)
      e.covariance(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) = row[k];
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!(e.covariance(i, i) >= 0))
      throw model::io::FormatError(
          file, fields::place(fields::element_path(matrix_at, static_cast<std::size_t>(i))),
          "expected a variance >= 0 on the diagonal");
    for (Eigen::Index k = 0; k < i; ++k)
      if (std::abs(e.covariance(i, k) - e.covariance(k, i)) >
          1e-12 * std::max(std::abs(e.covariance(i, k)), std::abs(e.covariance(k, i))))
        throw model::io::FormatError(file, fields::place(matrix_at),
                                     "expected a symmetric matrix (rows " + std::to_string(k) +
                                         " and " + std::to_string(i) + " differ)");
  }
  e.vibration_samples = static_cast<std::size_t>(
      fields::as_integer(fields::member(section, "vibration_samples", file, key), file,
                         fields::member_path(key, "vibration_samples"), 0, 1LL << 40));
  e.friction_samples = static_cast<std::size_t>(
      fields::as_integer(fields::member(section, "friction_samples", file, key), file,
                         fields::member_path(key, "friction_samples"), 0, 1LL << 40));
  return e;
}

}  // namespace

ReadPrediction read_prediction(const std::filesystem::path& file,
                               const model::measure::ThresholdCurve& threshold) {
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
  if (j.contains("descriptor_error_covariance"))
    tool.descriptor_errors = read_descriptor_errors(j, file);
  return {design::predicted_tool_entry(tool), design::predicted_pairing(tool, threshold.source()),
          tool.descriptor_errors};
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
