#include "model/design/prediction_file.hpp"

#include <algorithm>
#include <cmath>

#include "model/io/format_error.hpp"
#include "model/io/json_fields.hpp"
#include "model/measure/descriptors.hpp"

namespace nibrig::model::design {

nlohmann::json prediction_json(const PredictedTool& tool, const std::string& threshold_source) {
  nlohmann::json j = io::to_json(tool.spectrum);
  j["kind"] = "prediction";
  j["tool"] = to_string(tool.point);
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

namespace {

DescriptorErrorCovariance read_descriptor_errors(const nlohmann::json& j,
                                                 const std::filesystem::path& file) {
  namespace fields = io::json_fields;
  const std::string key = "descriptor_error_covariance";
  const auto& section = fields::as_object(j[key], file, key);
  DescriptorErrorCovariance e;
  const std::string names_at = fields::member_path(key, "names");
  const auto& names = fields::as_array(fields::member(section, "names", file, key), file, names_at);
  for (std::size_t i = 0; i < names.size(); ++i)
    e.names.push_back(fields::as_string(names[i], file, fields::element_path(names_at, i)));
  const std::string matrix_at = fields::member_path(key, "matrix");
  const auto& rows =
      fields::as_array(fields::member(section, "matrix", file, key), file, matrix_at);
  const auto n = static_cast<Eigen::Index>(e.names.size());
  if (rows.size() != e.names.size())
    throw io::FormatError(file, fields::place(matrix_at),
                          "expected one row per name (" + std::to_string(n) + ")");
  e.covariance.resize(n, n);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::string row_at = fields::element_path(matrix_at, i);
    const auto row = fields::as_number_array(rows[i], file, row_at);
    if (row.size() != e.names.size())
      throw io::FormatError(file, fields::place(row_at),
                            "expected one value per name (" + std::to_string(n) + ")");
    for (std::size_t k = 0; k < row.size(); ++k)
      e.covariance(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) = row[k];
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!(e.covariance(i, i) >= 0))
      throw io::FormatError(
          file, fields::place(fields::element_path(matrix_at, static_cast<std::size_t>(i))),
          "expected a variance >= 0 on the diagonal");
    for (Eigen::Index k = 0; k < i; ++k)
      if (std::abs(e.covariance(i, k) - e.covariance(k, i)) >
          1e-12 * std::max(std::abs(e.covariance(i, k)), std::abs(e.covariance(k, i))))
        throw io::FormatError(file, fields::place(matrix_at),
                              "expected a symmetric matrix (rows " + std::to_string(k) + " and " +
                                  std::to_string(i) + " differ)");
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

namespace {

DesignPoint predicted_point(const nlohmann::json& j, const std::filesystem::path& file) {
  namespace fields = io::json_fields;
  fields::as_object(j, file, "");
  if (fields::string_member(j, "kind", file, "") != "prediction")
    throw io::FormatError(file, fields::place("kind"),
                          "expected \"prediction\" (a `nibrig predict` file)");
  try {
    return parse_design_point(fields::string_member(j, "tool", file, ""));
  } catch (const std::invalid_argument& e) {
    throw io::FormatError(file, fields::place("tool"), e.what());
  }
}

}  // namespace

PredictedDesign read_predicted_design(const std::filesystem::path& file) {
  const nlohmann::json j = io::json_fields::parse_file(file);
  return {predicted_point(j, file), io::json_fields::string_member(j, "surface", file, "")};
}

ReadPrediction read_prediction(const std::filesystem::path& file,
                               const measure::ThresholdCurve& threshold) {
  namespace fields = io::json_fields;
  const nlohmann::json j = fields::parse_file(file);
  PredictedTool tool;
  tool.point = predicted_point(j, file);
  tool.surface = fields::string_member(j, "surface", file, "");
  tool.mu = fields::number_member(j, "mu", file, "");
  tool.spectrum = io::velocity_spectrum_from_json(j, file, "");
  tool.vibration = measure::compute_vibration_descriptors(tool.spectrum, threshold);
  if (j.contains("design") && j["design"].is_object() && j["design"].contains("name"))
    tool.design_name = fields::string_member(j["design"], "name", file, "design");
  if (j.contains("descriptor_error_covariance"))
    tool.descriptor_errors = read_descriptor_errors(j, file);
  return {tool.point, tool.surface, predicted_tool_entry(tool),
          predicted_pairing(tool, threshold.source()), tool.descriptor_errors};
}

}  // namespace nibrig::model::design
