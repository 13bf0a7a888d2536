#include "model/design/prediction_file.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "model/design/design_constraints.hpp"
#include "model/io/format_error.hpp"
#include "model/io/json_fields.hpp"
#include "model/measure/descriptors.hpp"
#include "model/mechanics/material_table.hpp"

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
  if (!tool.material_basis.empty()) j["design"]["material_basis"] = tool.material_basis;
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

namespace fields = io::json_fields;

// A prediction's own ranges: what predict_tool can write, with room, so that a hand-edited or
// damaged value is named instead of flowing into a placement or a print sheet. A drawing tool's μ
// is below 1 (the catalog holds friction to the same 10); a stylus's first mode lies in the
// hundreds of hertz and its spectrum's frequencies below the accelerometer's 1 kHz Nyquist, so
// 1 MHz and 10 m/s (the fastest stroke a face plays) are far outside anything written.
constexpr double kPredictionMaxMu = 10.0;
constexpr double kPredictionMaxHz = 1e6;
constexpr double kPredictionMaxSpeedMmS = 1e4;
// design.tip_diameter_mm and design.mix repeat the "tool" string, which to_string writes to six
// significant digits: they agree to within half a unit of the sixth digit (5e-6 relative).
constexpr double kPredictionRepeatTolerance = 1e-5;

bool prediction_agrees(double a, double b) {
  return std::abs(a - b) <= kPredictionRepeatTolerance * std::max(std::abs(a), std::abs(b));
}

std::string prediction_number(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

bool prediction_bool(const nlohmann::json& value, const std::filesystem::path& file, const std::string& path) {
  if (!value.is_boolean())
    throw io::FormatError(file, fields::place(path), "expected true or false, found " + value.dump());
  return value.get<bool>();
}

void check_prediction_strings(const nlohmann::json& value, const std::filesystem::path& file, const std::string& path) {
  const auto& array = fields::as_array(value, file, path);
  for (std::size_t i = 0; i < array.size(); ++i) fields::as_string(array[i], file, fields::element_path(path, i));
}

// descriptors: recomputed from the spectrum on reading, but a file whose own are damaged is
// damaged: each checked to its type (numbers >= 0; band_energies keyed by their count).
void check_written_descriptors(const nlohmann::json& j, const std::filesystem::path& file) {
  const auto& d = fields::as_object(fields::member(j, "descriptors", file, ""), file, "descriptors");
  for (const char* key : {"weighted_mean", "weighted_power"})
    fields::as_number_in(fields::member(d, key, file, "descriptors"), file, fields::member_path("descriptors", key),
                         0.0, fields::kMaxJsonMagnitude, "a descriptor of a spectrum, >= 0");
  const std::string bands_at = fields::member_path("descriptors", "band_energies");
  const auto& bands = fields::as_object(fields::member(d, "band_energies", file, "descriptors"), file, bands_at);
  for (const auto& [key, value] : bands.items()) {
    const std::string band_at = fields::member_path(bands_at, key);
    const bool digits = !key.empty() && key.size() <= 4 && key.find_first_not_of("0123456789") == std::string::npos;
    const int k = digits ? std::stoi(key) : 0;
    if (k < 1) throw io::FormatError(file, fields::place(band_at), "expected a band count >= 1 as key, found \"" + key + "\"");
    const auto energies = fields::as_number_array_in(value, file, band_at, 0.0, fields::kMaxJsonMagnitude,
                                                     "a band's energy, >= 0");
    if (energies.size() != static_cast<std::size_t>(k))
      throw io::FormatError(file, fields::place(band_at),
                            "expected " + std::to_string(k) + " band energies, found " + std::to_string(energies.size()));
  }
}

// design: the stylus the prediction solved; its tip and mix repeat the tool's and must agree.
void check_written_design(const nlohmann::json& j, const DesignPoint& point, const std::filesystem::path& file) {
  const auto& d = fields::as_object(fields::member(j, "design", file, ""), file, "design");
  fields::string_member(d, "name", file, "design");
  fields::as_number_in(fields::member(d, "first_mode_hz", file, "design"), file,
                       fields::member_path("design", "first_mode_hz"), 0.0, kPredictionMaxHz,
                       "a stylus's first mode in Hz");
  const std::string tip_at = fields::member_path("design", "tip_diameter_mm");
  const double tip_mm = fields::as_number_in(fields::member(d, "tip_diameter_mm", file, "design"), file, tip_at,
                                             kSmallestConstraintTipMm, kLargestConstraintTipMm, "a tip diameter in mm");
  if (!prediction_agrees(tip_mm, point.tip_diameter_m * 1e3))
    throw io::FormatError(file, fields::place(tip_at),
                          "found " + prediction_number(tip_mm) + " mm, expected the tool's tip, " +
                              prediction_number(point.tip_diameter_m * 1e3) + " mm");
  if (d.contains("material_basis") &&
      !mechanics::is_material_basis(fields::string_member(d, "material_basis", file, "design")))
    throw io::FormatError(file, fields::place(fields::member_path("design", "material_basis")),
                          "expected fitted, datasheet or estimate");
  const std::string mix_at = fields::member_path("design", "mix");
  const auto& mix = fields::as_object(fields::member(d, "mix", file, "design"), file, mix_at);
  for (const auto& [material, value] : mix.items()) {
    const std::string at = fields::member_path(mix_at, material);
    const double fraction = fields::as_number_in(value, file, at, 0.0, 1.0, "a material's share of the mix");
    if (!prediction_agrees(fraction, point.fraction_of(material)))
      throw io::FormatError(file, fields::place(at),
                            "found " + prediction_number(fraction) + ", expected the tool's share of " + material +
                                ", " + prediction_number(point.fraction_of(material)));
  }
  for (const auto& share : point.mix)
    if (!mix.contains(share.material))
      throw io::FormatError(file, fields::place(mix_at), "expected a share of " + share.material + ", as the tool has");
}

// comparison (predict --against): the error against a measurement, in dB.
void check_written_comparison(const nlohmann::json& j, const std::filesystem::path& file) {
  const auto it = j.find("comparison");
  if (it == j.end()) return;
  const std::string at = "comparison";
  const auto& c = fields::as_object(*it, file, at);
  const auto check_errors = [&](const nlohmann::json& object, const std::string& parent) {
    fields::as_number_in(fields::member(object, "rms_db", file, parent), file, fields::member_path(parent, "rms_db"), 0.0,
                         fields::kMaxJsonMagnitude, "an RMS error in dB, >= 0");
    fields::as_number_array_in(fields::member(object, "rms_db_by_speed", file, parent), file,
                               fields::member_path(parent, "rms_db_by_speed"), 0.0, fields::kMaxJsonMagnitude,
                               "an RMS error in dB, >= 0");
  };
  fields::string_member(c, "against", file, at);
  check_errors(c, at);
  const std::string baselines_at = fields::member_path(at, "no_interpolation_baselines");
  const auto& baselines =
      fields::as_array(fields::member(c, "no_interpolation_baselines", file, at), file, baselines_at);
  for (std::size_t i = 0; i < baselines.size(); ++i) {
    const std::string b_at = fields::element_path(baselines_at, i);
    fields::as_object(baselines[i], file, b_at);
    fields::string_member(baselines[i], "scalings_of", file, b_at);
    check_errors(baselines[i], b_at);
  }
  prediction_bool(fields::member(c, "beats_every_baseline", file, at), file, fields::member_path(at, "beats_every_baseline"));
}

// Every field prediction_json writes, checked to its type and range whether a reader uses it or not,
// so that a damaged file is refused by every command that opens it (space embed --predicted,
// export), naming the file and the field. Returns the design and the surface.
PredictedDesign checked_prediction(const nlohmann::json& j, const std::filesystem::path& file) {
  fields::as_object(j, file, "");
  if (fields::string_member(j, "kind", file, "") != "prediction")
    throw io::FormatError(file, fields::place("kind"),
                          "expected \"prediction\" (a `nibrig predict` file)");
  PredictedDesign out;
  try {
    out.point = parse_design_point(fields::string_member(j, "tool", file, ""));
  } catch (const std::invalid_argument& e) {
    throw io::FormatError(file, fields::place("tool"), e.what());
  }
  out.surface = fields::string_member(j, "surface", file, "");
  if (out.surface.empty()) throw io::FormatError(file, fields::place("surface"), "expected a surface id, found \"\"");
  fields::as_number_in(fields::member(j, "mu", file, ""), file, "mu", 0.0, kPredictionMaxMu,
                       "a friction coefficient: a drawing tool's is below 1");
  const io::VelocitySpectrum spectrum = io::velocity_spectrum_from_json(j, file, "");
  for (std::size_t i = 0; i < spectrum.frequencies_hz.size(); ++i)
    if (spectrum.frequencies_hz[i] > kPredictionMaxHz)
      throw io::FormatError(file, fields::place(fields::element_path("frequencies_hz", i)),
                            "found " + prediction_number(spectrum.frequencies_hz[i]) + ", expected a frequency of at most " +
                                prediction_number(kPredictionMaxHz) + " Hz");
  for (std::size_t i = 0; i < spectrum.speeds_m_s.size(); ++i)
    if (!(spectrum.speeds_m_s[i] > 0.0 && spectrum.speeds_m_s[i] * 1e3 <= kPredictionMaxSpeedMmS))
      throw io::FormatError(file, fields::place(fields::element_path("speeds_mm_s", i)),
                            "found " + prediction_number(spectrum.speeds_m_s[i] * 1e3) + ", expected a speed in mm/s, above 0 and at most " +
                                prediction_number(kPredictionMaxSpeedMmS));
  check_written_descriptors(j, file);
  fields::string_member(j, "threshold_curve", file, "");
  check_written_design(j, out.point, file);
  check_prediction_strings(fields::member(j, "notes", file, ""), file, "notes");
  check_written_comparison(j, file);
  return out;
}

}  // namespace

PredictedDesign read_predicted_design(const std::filesystem::path& file) {
  const nlohmann::json j = io::json_fields::parse_file(file);
  PredictedDesign out = checked_prediction(j, file);
  if (j.contains("descriptor_error_covariance")) read_descriptor_errors(j, file);
  return out;
}

ReadPrediction read_prediction(const std::filesystem::path& file,
                               const measure::ThresholdCurve& threshold) {
  namespace fields = io::json_fields;
  const nlohmann::json j = fields::parse_file(file);
  PredictedTool tool;
  PredictedDesign design = checked_prediction(j, file);
  tool.point = std::move(design.point);
  tool.surface = std::move(design.surface);
  tool.mu = fields::number_member(j, "mu", file, "");
  tool.spectrum = io::velocity_spectrum_from_json(j, file, "");
  tool.vibration = measure::compute_vibration_descriptors(tool.spectrum, threshold);
  tool.design_name = fields::string_member(j["design"], "name", file, "design");
  tool.first_mode_hz = fields::number_member(j["design"], "first_mode_hz", file, "design");
  if (j["design"].contains("material_basis")) tool.material_basis = j["design"]["material_basis"].get<std::string>();
  if (j.contains("descriptor_error_covariance"))
    tool.descriptor_errors = read_descriptor_errors(j, file);
  return {tool.point, tool.surface, predicted_tool_entry(tool),
          predicted_pairing(tool, threshold.source()), tool.descriptor_errors};
}

}  // namespace nibrig::model::design
