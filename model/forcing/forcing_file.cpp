#include "model/forcing/forcing_file.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "model/io/atomic_file.hpp"
#include "model/io/format_error.hpp"
#include "model/io/json_fields.hpp"
#include "model/io/finite_output.hpp"

namespace nibrig::model::forcing {

namespace {

namespace jf = io::json_fields;
using nlohmann::json;

constexpr const char* kFormat = "nibrig-forcing";

std::vector<double> scaled(const std::vector<double>& values, double factor) {
  std::vector<double> out;
  for (double v : values) out.push_back(v * factor);
  return out;
}

void require(bool ok, const std::filesystem::path& file, const std::string& path,
             const std::string& expected) {
  if (!ok) throw io::FormatError(file, jf::place(path), expected);
}

std::vector<double> increasing_array(const json& root, const std::string& key,
                                     const std::filesystem::path& file, std::size_t min_size) {
  const auto values = jf::as_number_array(jf::member(root, key, file, ""), file, key);
  require(values.size() >= min_size, file, key,
          "expected at least " + std::to_string(min_size) + " values");
  for (std::size_t k = 1; k < values.size(); ++k)
    require(values[k] > values[k - 1], file, jf::element_path(key, k),
            "expected strictly increasing values");
  return values;
}

std::vector<double> curve_at(const json& entry, const std::filesystem::path& file,
                             const std::string& at, std::size_t knots) {
  const std::string path = jf::member_path(at, "log_gain");
  // A gain of e^±50 (about 1e±22) is far outside anything a curve fitted to the catalog reaches,
  // and the squares and sums taken of it stay finite.
  const auto values = jf::as_number_array_in(jf::member(entry, "log_gain", file, at), file, path,
                                             -50.0, 50.0, "a natural-log gain");
  require(values.size() == knots, file, path,
          "expected one value per knot (" + std::to_string(knots) + "), found " +
              std::to_string(values.size()));
  return values;
}

// A calibration's standard errors of natural-log values: one per knot or frequency, each finite
// and >= 0 (50, like the gains' bound, is far beyond what any calibration reports).
std::vector<double> standard_errors_at(const json& values, const std::filesystem::path& file,
                                       const std::string& path, std::size_t count,
                                       const std::string& per) {
  auto out = jf::as_number_array_in(values, file, path, 0.0, 50.0,
                                    "a standard error of a natural log (>= 0)");
  require(out.size() == count, file, path,
          "expected one value per " + per + " (" + std::to_string(count) + "), found " +
              std::to_string(out.size()));
  return out;
}

nlohmann::json descriptor_errors_json(const ForcingModel& model) {
  json exemplars = json::array();
  for (const auto& e : model.held_out_descriptor_errors) {
    json bands = json::object();
    for (const auto& [k, values] : e.log10_band_energies) bands[std::to_string(k)] = values;
    exemplars.push_back({{"tool", e.tool},
                         {"surface", e.surface},
                         {"log10_weighted_mean", e.log10_weighted_mean},
                         {"log10_band_energies", bands}});
  }
  return {{"threshold_curve", model.descriptor_error_threshold}, {"exemplars", exemplars}};
}

void read_descriptor_errors(const json& root, const std::filesystem::path& file,
                            ForcingModel& model) {
  const std::string key = "held_out_descriptor_errors";
  const auto& section = jf::as_object(root[key], file, key);
  model.descriptor_error_threshold = jf::string_member(section, "threshold_curve", file, key);
  const std::string list = jf::member_path(key, "exemplars");
  const auto& exemplars = jf::as_array(jf::member(section, "exemplars", file, key), file, list);
  for (std::size_t i = 0; i < exemplars.size(); ++i) {
    const std::string at = jf::element_path(list, i);
    DescriptorError e;
    e.tool = jf::string_member(exemplars[i], "tool", file, at);
    e.surface = jf::string_member(exemplars[i], "surface", file, at);
    e.log10_weighted_mean = jf::number_member(exemplars[i], "log10_weighted_mean", file, at);
    const std::string bands_at = jf::member_path(at, "log10_band_energies");
    const auto& bands =
        jf::as_object(jf::member(exemplars[i], "log10_band_energies", file, at), file, bands_at);
    for (int k = kMinDescriptorBands; k <= kMaxDescriptorBands; ++k) {
      const std::string band_at = jf::member_path(bands_at, std::to_string(k));
      auto values =
          jf::as_number_array(jf::member(bands, std::to_string(k), file, bands_at), file, band_at);
      require(
          values.size() == static_cast<std::size_t>(k), file, band_at,
          "expected " + std::to_string(k) + " band values, found " + std::to_string(values.size()));
      e.log10_band_energies[k] = std::move(values);
    }
    model.held_out_descriptor_errors.push_back(std::move(e));
  }
}

bool all_zero(const std::vector<double>& values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return v == 0.0; });
}

// The model a forcing file's JSON holds, checked field by field.
ForcingModel model_of_json(const json& root, const std::filesystem::path& file);

}  // namespace

std::string forcing_model_text(const ForcingModel& model, const std::filesystem::path& file) {
  json out;
  out["format"] = kFormat;
  out["version"] = 1;
  out["knot_frequencies_hz"] = model.knot_frequencies_hz;
  out["reference"] = {{"tip_diameter_mm", model.reference_tip_diameter_m * 1e3},
                      {"material", model.reference_material}};
  out["tip_curves"] = json::array();
  for (const auto& [diameter, curve] : model.tip_log_gain)
    out["tip_curves"].push_back({{"tip_diameter_mm", diameter * 1e3}, {"log_gain", curve}});
  out["material_curves"] = json::array();
  for (const auto& [material, curve] : model.material_log_gain) {
    json entry = {{"material", material}, {"log_gain", curve}};
    if (const auto se = model.material_log_gain_se.find(material);
        se != model.material_log_gain_se.end())
      entry["log_gain_se"] = se->second;
    out["material_curves"].push_back(entry);
  }
  out["frequencies_hz"] = model.frequencies_hz;
  out["speeds_mm_s"] = scaled(model.speeds_m_s, 1e3);
  out["surfaces"] = json::array();
  for (const auto& [id, forcing] : model.surface_forcing) {
    json entry = {{"id", id}, {"forcing_n", forcing}};
    if (const auto se = model.surface_log_forcing_se.find(id);
        se != model.surface_log_forcing_se.end())
      entry["log_forcing_se"] = se->second;
    out["surfaces"].push_back(entry);
  }
  json exemplars = json::array();
  for (const auto& e : model.exemplar_fits)
    exemplars.push_back({{"tool", e.tool}, {"surface", e.surface}, {"rms_db", e.rms_db}});
  out["fit"] = {{"residual_rms_db", model.residual_rms_db},
                {"observations", model.observations},
                {"skipped_nonpositive", model.skipped_nonpositive},
                {"exemplars", exemplars}};
  if (!model.held_out_descriptor_errors.empty())
    out["held_out_descriptor_errors"] = descriptor_errors_json(model);
  out["notes"] = model.notes;
  return io::json_text(out, file, 1);
}

void write_forcing_model(const std::filesystem::path& file, const ForcingModel& model) {
  io::write_file_atomically(file, forcing_model_text(model, file));
}

ForcingModel read_forcing_model(const std::filesystem::path& file) {
  return model_of_json(jf::parse_file(file), file);
}

ForcingModel parse_forcing_model(const std::string& text, const std::filesystem::path& file) {
  return model_of_json(jf::parse_text(text, file), file);
}

namespace {

ForcingModel model_of_json(const json& root, const std::filesystem::path& file) {
  jf::as_object(root, file, "");
  jf::check_format_and_version(root, file, kFormat, 1);
  ForcingModel model;

  model.knot_frequencies_hz = increasing_array(root, "knot_frequencies_hz", file, 2);
  const std::size_t knots = model.knot_frequencies_hz.size();

  const auto& reference = jf::as_object(jf::member(root, "reference", file, ""), file, "reference");
  model.reference_tip_diameter_m =
      jf::number_member(reference, "tip_diameter_mm", file, "reference") * 1e-3;
  require(model.reference_tip_diameter_m > 0, file, "reference.tip_diameter_mm",
          "expected a positive diameter");
  model.reference_material = jf::string_member(reference, "material", file, "reference");

  const auto& tips = jf::as_array(jf::member(root, "tip_curves", file, ""), file, "tip_curves");
  for (std::size_t i = 0; i < tips.size(); ++i) {
    const std::string at = jf::element_path("tip_curves", i);
    const double d = jf::number_member(tips[i], "tip_diameter_mm", file, at) * 1e-3;
    require(d > 0, file, jf::member_path(at, "tip_diameter_mm"), "expected a positive diameter");
    for (const auto& [known, curve] : model.tip_log_gain)
      require(!same_tip(known, d), file, jf::member_path(at, "tip_diameter_mm"),
              "a second curve for the same tip");
    model.tip_log_gain[d] = curve_at(tips[i], file, at, knots);
  }
  const auto& materials =
      jf::as_array(jf::member(root, "material_curves", file, ""), file, "material_curves");
  for (std::size_t i = 0; i < materials.size(); ++i) {
    const std::string at = jf::element_path("material_curves", i);
    const std::string name = jf::string_member(materials[i], "material", file, at);
    require(!model.material_log_gain.count(name), file, jf::member_path(at, "material"),
            "a second curve for material '" + name + "'");
    model.material_log_gain[name] = curve_at(materials[i], file, at, knots);
    if (materials[i].contains("log_gain_se"))
      model.material_log_gain_se[name] = standard_errors_at(
          materials[i]["log_gain_se"], file, jf::member_path(at, "log_gain_se"), knots, "knot");
  }
  // The gauge: the reference tip and material must be there, at gain 1.
  bool reference_tip = false;
  for (const auto& [d, curve] : model.tip_log_gain)
    if (same_tip(d, model.reference_tip_diameter_m)) {
      require(all_zero(curve), file, "tip_curves",
              "the reference tip's log_gain must be all zeros (it fixes the scale)");
      reference_tip = true;
    }
  require(reference_tip, file, "tip_curves", "expected a curve for the reference tip");
  const auto ref_material = model.material_log_gain.find(model.reference_material);
  require(ref_material != model.material_log_gain.end(), file, "material_curves",
          "expected a curve for the reference material '" + model.reference_material + "'");
  require(all_zero(ref_material->second), file, "material_curves",
          "the reference material's log_gain must be all zeros (it fixes the scale)");

  model.frequencies_hz = increasing_array(root, "frequencies_hz", file, 1);
  require(model.frequencies_hz.front() >= model.knot_frequencies_hz.front() &&
              model.frequencies_hz.back() <= model.knot_frequencies_hz.back(),
          file, "frequencies_hz", "expected frequencies within the knots");
  model.speeds_m_s = scaled(increasing_array(root, "speeds_mm_s", file, 1), 1e-3);
  require(model.speeds_m_s.front() >= 0, file, "speeds_mm_s", "expected speeds >= 0");

  const auto& surfaces = jf::as_array(jf::member(root, "surfaces", file, ""), file, "surfaces");
  require(!surfaces.empty(), file, "surfaces", "expected at least one surface");
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    const std::string at = jf::element_path("surfaces", i);
    const std::string id = jf::string_member(surfaces[i], "id", file, at);
    require(!model.surface_forcing.count(id), file, jf::member_path(at, "id"),
            "a second entry for surface '" + id + "'");
    const std::string rows_at = jf::member_path(at, "forcing_n");
    const auto& rows = jf::as_array(jf::member(surfaces[i], "forcing_n", file, at), file, rows_at);
    require(rows.size() == model.speeds_m_s.size(), file, rows_at,
            "expected one row per speed (" + std::to_string(model.speeds_m_s.size()) + "), found " +
                std::to_string(rows.size()));
    auto& forcing = model.surface_forcing[id];
    for (std::size_t s = 0; s < rows.size(); ++s) {
      const std::string row_at = jf::element_path(rows_at, s);
      auto row = jf::as_number_array(rows[s], file, row_at);
      require(row.size() == model.frequencies_hz.size(), file, row_at,
              "expected one value per frequency (" + std::to_string(model.frequencies_hz.size()) +
                  "), found " + std::to_string(row.size()));
      for (std::size_t j = 0; j < row.size(); ++j)
        require(row[j] >= 0, file, jf::element_path(row_at, j), "expected a force >= 0 N");
      forcing.push_back(std::move(row));
    }
    if (surfaces[i].contains("log_forcing_se")) {
      const std::string se_at = jf::member_path(at, "log_forcing_se");
      const auto& se_rows = jf::as_array(surfaces[i]["log_forcing_se"], file, se_at);
      require(se_rows.size() == model.speeds_m_s.size(), file, se_at,
              "expected one row per speed (" + std::to_string(model.speeds_m_s.size()) +
                  "), found " + std::to_string(se_rows.size()));
      auto& se = model.surface_log_forcing_se[id];
      for (std::size_t s = 0; s < se_rows.size(); ++s)
        se.push_back(standard_errors_at(se_rows[s], file, jf::element_path(se_at, s),
                                        model.frequencies_hz.size(), "frequency"));
    }
  }

  const auto& fit = jf::as_object(jf::member(root, "fit", file, ""), file, "fit");
  model.residual_rms_db = jf::number_member(fit, "residual_rms_db", file, "fit");
  model.observations = static_cast<std::size_t>(jf::as_integer(
      jf::member(fit, "observations", file, "fit"), file, "fit.observations", 0, 1LL << 50));
  model.skipped_nonpositive =
      static_cast<std::size_t>(jf::as_integer(jf::member(fit, "skipped_nonpositive", file, "fit"),
                                              file, "fit.skipped_nonpositive", 0, 1LL << 50));
  const auto& exemplars =
      jf::as_array(jf::member(fit, "exemplars", file, "fit"), file, "fit.exemplars");
  for (std::size_t i = 0; i < exemplars.size(); ++i) {
    const std::string at = jf::element_path("fit.exemplars", i);
    model.exemplar_fits.push_back({jf::string_member(exemplars[i], "tool", file, at),
                                   jf::string_member(exemplars[i], "surface", file, at),
                                   jf::number_member(exemplars[i], "rms_db", file, at)});
  }
  if (root.contains("held_out_descriptor_errors")) read_descriptor_errors(root, file, model);
  if (root.contains("notes")) {
    const auto& notes = jf::as_array(root["notes"], file, "notes");
    for (std::size_t i = 0; i < notes.size(); ++i)
      model.notes.push_back(jf::as_string(notes[i], file, jf::element_path("notes", i)));
  }
  return model;
}

}  // namespace

}  // namespace nibrig::model::forcing
