#include "model/io/catalog_file.hpp"

#include <set>

#include "model/io/atomic_file.hpp"
#include "model/io/finite_output.hpp"
#include "model/io/format_error.hpp"
#include "model/io/json_fields.hpp"

namespace nibrig::model::io {

namespace {

using namespace json_fields;

// Physical ranges, so that a damaged or hand-edited catalog is refused before 1e300 turns into
// inf in an embedding or a forcing fit.
constexpr double kMaxMu = 10.0;
constexpr const char* kMuRange = "a friction coefficient: a drawing tool's is below 1";
constexpr double kMaxAmplitude = 1e4;
constexpr const char* kAmplitudeRange =
    "an acceleration amplitude in m/s²: 1000 g, far beyond any stylus";

constexpr const char* kCatalogFormat = "nibrig-catalog";
constexpr int kCatalogVersion = 1;
constexpr int kMostBands = 1000;
const std::set<std::string> kKinds = {"real", "printed", "commercial", "predicted", "unknown"};

std::vector<double> to_mm(const std::vector<double>& metres) {
  std::vector<double> mm;
  mm.reserve(metres.size());
  for (double v : metres) mm.push_back(v * 1e3);
  return mm;
}

std::vector<double> to_m(const std::vector<double>& millimetres) {
  std::vector<double> m;
  m.reserve(millimetres.size());
  for (double v : millimetres) m.push_back(v * 1e-3);
  return m;
}

void require_increasing(const std::vector<double>& values, const std::filesystem::path& file,
                        const std::string& path, const char* what) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (values[i] < 0.0) {
      throw FormatError(
          file, place(element_path(path, i)),
          std::string("expected ") + what + " >= 0, found " + nlohmann::json(values[i]).dump());
    }
    if (i > 0 && values[i] <= values[i - 1]) {
      throw FormatError(file, place(element_path(path, i)),
                        std::string("expected ") + what + " in increasing order, found " +
                            nlohmann::json(values[i]).dump() + " after " +
                            nlohmann::json(values[i - 1]).dump());
    }
  }
}

nlohmann::json provenance_json(const Provenance& p) {
  return {{"source", p.source}, {"method", p.method}};
}

Provenance provenance_from(const nlohmann::json& parent, const std::filesystem::path& file,
                           const std::string& parent_path) {
  const nlohmann::json& json = member(parent, "provenance", file, parent_path);
  const std::string path = member_path(parent_path, "provenance");
  return {string_member(json, "source", file, path), string_member(json, "method", file, path)};
}

nlohmann::json friction_json(const FrictionDescriptor& f) {
  return {{"mu", f.mu},
          {"mu_ci_low", f.mu_ci_low},
          {"mu_ci_high", f.mu_ci_high},
          {"samples", f.samples},
          {"speeds_mm_s", to_mm(f.speeds_m_s)},
          {"mu_by_speed", f.mu_by_speed},
          {"provenance", provenance_json(f.provenance)}};
}

FrictionDescriptor friction_from(const nlohmann::json& json, const std::filesystem::path& file,
                                 const std::string& path) {
  as_object(json, file, path);
  FrictionDescriptor f;
  f.mu = as_number_in(member(json, "mu", file, path), file, member_path(path, "mu"), 0.0, kMaxMu,
                      kMuRange);
  f.mu_ci_low = as_number_in(member(json, "mu_ci_low", file, path), file,
                             member_path(path, "mu_ci_low"), 0.0, kMaxMu, kMuRange);
  f.mu_ci_high = as_number_in(member(json, "mu_ci_high", file, path), file,
                              member_path(path, "mu_ci_high"), 0.0, kMaxMu, kMuRange);
  if (f.mu_ci_low > f.mu_ci_high) {
    throw FormatError(file, place(member_path(path, "mu_ci_high")),
                      "expected the interval's upper end >= its lower end (" +
                          nlohmann::json(f.mu_ci_low).dump() + "), found " +
                          nlohmann::json(f.mu_ci_high).dump());
  }
  f.samples = static_cast<std::size_t>(as_integer(member(json, "samples", file, path), file,
                                                  member_path(path, "samples"), 0, INT64_MAX));
  const std::string speeds_path = member_path(path, "speeds_mm_s");
  const std::vector<double> speeds_mm =
      as_number_array(member(json, "speeds_mm_s", file, path), file, speeds_path);
  require_increasing(speeds_mm, file, speeds_path, "speeds");
  f.speeds_m_s = to_m(speeds_mm);
  const std::string mu_path = member_path(path, "mu_by_speed");
  f.mu_by_speed = as_number_array_in(member(json, "mu_by_speed", file, path), file, mu_path, 0.0,
                                     kMaxMu, kMuRange);
  if (f.mu_by_speed.size() != f.speeds_m_s.size()) {
    throw FormatError(file, place(mu_path),
                      "expected one value per speed (" + std::to_string(f.speeds_m_s.size()) +
                          "), found " + std::to_string(f.mu_by_speed.size()));
  }
  f.provenance = provenance_from(json, file, path);
  return f;
}

nlohmann::json vibration_json(const VibrationDescriptor& v) {
  nlohmann::json json = to_json(v.spectrum);
  json["weighted_mean"] = v.weighted_mean;
  json["weighted_power"] = v.weighted_power;
  nlohmann::json bands = nlohmann::json::object();
  for (const auto& [k, energies] : v.band_energies) bands[std::to_string(k)] = energies;
  json["band_energies"] = bands;
  json["threshold_curve"] = v.threshold_curve;
  json["provenance"] = provenance_json(v.provenance);
  return json;
}

VibrationDescriptor vibration_from(const nlohmann::json& json, const std::filesystem::path& file,
                                   const std::string& path) {
  VibrationDescriptor v;
  v.spectrum = velocity_spectrum_from_json(json, file, path);
  v.weighted_mean = number_member(json, "weighted_mean", file, path);
  v.weighted_power = number_member(json, "weighted_power", file, path);
  const std::string bands_path = member_path(path, "band_energies");
  const nlohmann::json& bands =
      as_object(member(json, "band_energies", file, path), file, bands_path);
  for (const auto& [key, value] : bands.items()) {
    const std::string band_path = member_path(bands_path, key);
    int k = 0;
    const bool digits_only =
        !key.empty() && key.size() <= 4 && key.find_first_not_of("0123456789") == std::string::npos;
    if (digits_only) k = std::stoi(key);
    if (!digits_only || k < 1 || k > kMostBands) {
      throw FormatError(file, place(band_path),
                        "expected a band count 1-" + std::to_string(kMostBands) +
                            " as key, found \"" + key + "\"");
    }
    std::vector<double> energies = as_number_array(value, file, band_path);
    if (energies.size() != static_cast<std::size_t>(k)) {
      throw FormatError(file, place(band_path),
                        "expected " + std::to_string(k) + " band energies, found " +
                            std::to_string(energies.size()));
    }
    v.band_energies[k] = std::move(energies);
  }
  v.threshold_curve = string_member(json, "threshold_curve", file, path);
  v.provenance = provenance_from(json, file, path);
  return v;
}

nlohmann::json catalog_json(const Catalog& catalog) {
  nlohmann::json tools = nlohmann::json::array();
  for (const ToolEntry& t : catalog.tools) {
    nlohmann::json tool = {
        {"id", t.id}, {"name", t.name}, {"kind", t.kind}, {"material", t.material}};
    if (t.tip_diameter_m) tool["tip_diameter_mm"] = *t.tip_diameter_m * 1e3;
    tools.push_back(std::move(tool));
  }
  nlohmann::json surfaces = nlohmann::json::array();
  for (const SurfaceEntry& s : catalog.surfaces)
    surfaces.push_back({{"id", s.id}, {"name", s.name}});
  nlohmann::json pairings = nlohmann::json::array();
  for (const Pairing& p : catalog.pairings) {
    nlohmann::json pairing = {{"tool", p.tool}, {"surface", p.surface}};
    if (p.friction) pairing["friction"] = friction_json(*p.friction);
    if (p.vibration) pairing["vibration"] = vibration_json(*p.vibration);
    pairings.push_back(std::move(pairing));
  }
  return {{"format", kCatalogFormat},     {"version", kCatalogVersion},  {"citation", catalog.citation},
          {"tools", tools},        {"surfaces", surfaces}, {"pairings", pairings},
          {"notes", catalog.notes}};
}

Catalog catalog_from(const nlohmann::json& json, const std::filesystem::path& file) {
  as_object(json, file, "");
  check_format_and_version(json, file, kCatalogFormat, kCatalogVersion);
  Catalog catalog;
  catalog.citation = string_member(json, "citation", file, "");

  std::set<std::string> tool_ids;
  const nlohmann::json& tools = as_array(member(json, "tools", file, ""), file, "tools");
  for (std::size_t i = 0; i < tools.size(); ++i) {
    const std::string path = element_path("tools", i);
    as_object(tools[i], file, path);
    ToolEntry t;
    t.id = string_member(tools[i], "id", file, path);
    if (t.id.empty())
      throw FormatError(file, place(member_path(path, "id")), "expected a tool id, found \"\"");
    if (!tool_ids.insert(t.id).second) {
      throw FormatError(file, place(member_path(path, "id")),
                        "tool id \"" + t.id + "\" listed twice");
    }
    t.name = string_member(tools[i], "name", file, path);
    t.kind = string_member(tools[i], "kind", file, path);
    if (kKinds.count(t.kind) == 0) {
      throw FormatError(
          file, place(member_path(path, "kind")),
          "expected real, printed, commercial, predicted or unknown, found \"" + t.kind + "\"");
    }
    t.material = string_member(tools[i], "material", file, path);
    if (const auto it = tools[i].find("tip_diameter_mm"); it != tools[i].end()) {
      const double mm = as_number(*it, file, member_path(path, "tip_diameter_mm"));
      if (mm <= 0.0) {
        throw FormatError(file, place(member_path(path, "tip_diameter_mm")),
                          "expected a positive diameter, found " + it->dump());
      }
      t.tip_diameter_m = mm * 1e-3;
    }
    catalog.tools.push_back(std::move(t));
  }

  std::set<std::string> surface_ids;
  const nlohmann::json& surfaces = as_array(member(json, "surfaces", file, ""), file, "surfaces");
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    const std::string path = element_path("surfaces", i);
    as_object(surfaces[i], file, path);
    SurfaceEntry s{string_member(surfaces[i], "id", file, path),
                   string_member(surfaces[i], "name", file, path)};
    if (s.id.empty())
      throw FormatError(file, place(member_path(path, "id")), "expected a surface id, found \"\"");
    if (!surface_ids.insert(s.id).second) {
      throw FormatError(file, place(member_path(path, "id")),
                        "surface id \"" + s.id + "\" listed twice");
    }
    catalog.surfaces.push_back(std::move(s));
  }

  std::set<std::pair<std::string, std::string>> seen_pairs;
  const nlohmann::json& pairings = as_array(member(json, "pairings", file, ""), file, "pairings");
  for (std::size_t i = 0; i < pairings.size(); ++i) {
    const std::string path = element_path("pairings", i);
    as_object(pairings[i], file, path);
    Pairing p;
    p.tool = string_member(pairings[i], "tool", file, path);
    if (tool_ids.count(p.tool) == 0) {
      throw FormatError(file, place(member_path(path, "tool")),
                        "expected a tool id listed in tools, found \"" + p.tool + "\"");
    }
    p.surface = string_member(pairings[i], "surface", file, path);
    if (surface_ids.count(p.surface) == 0) {
      throw FormatError(file, place(member_path(path, "surface")),
                        "expected a surface id listed in surfaces, found \"" + p.surface + "\"");
    }
    if (!seen_pairs.emplace(p.tool, p.surface).second) {
      throw FormatError(file, place(path),
                        "pairing " + p.tool + " on " + p.surface + " listed twice");
    }
    if (const auto it = pairings[i].find("friction"); it != pairings[i].end()) {
      p.friction = friction_from(*it, file, member_path(path, "friction"));
    }
    if (const auto it = pairings[i].find("vibration"); it != pairings[i].end()) {
      p.vibration = vibration_from(*it, file, member_path(path, "vibration"));
    }
    catalog.pairings.push_back(std::move(p));
  }

  const nlohmann::json& notes = as_array(member(json, "notes", file, ""), file, "notes");
  for (std::size_t i = 0; i < notes.size(); ++i) {
    catalog.notes.push_back(as_string(notes[i], file, element_path("notes", i)));
  }
  return catalog;
}

}  // namespace

nlohmann::json to_json(const VelocitySpectrum& spectrum) {
  return {{"frequencies_hz", spectrum.frequencies_hz},
          {"speeds_mm_s", to_mm(spectrum.speeds_m_s)},
          {"amplitude_m_s2", spectrum.amplitude_m_s2}};
}

VelocitySpectrum velocity_spectrum_from_json(const nlohmann::json& json,
                                             const std::filesystem::path& file,
                                             const std::string& where) {
  as_object(json, file, where);
  VelocitySpectrum spectrum;
  const std::string f_path = member_path(where, "frequencies_hz");
  spectrum.frequencies_hz =
      as_number_array(member(json, "frequencies_hz", file, where), file, f_path);
  if (spectrum.frequencies_hz.empty())
    throw FormatError(file, place(f_path), "expected at least one frequency, found none");
  require_increasing(spectrum.frequencies_hz, file, f_path, "frequencies");
  const std::string s_path = member_path(where, "speeds_mm_s");
  const std::vector<double> speeds_mm =
      as_number_array(member(json, "speeds_mm_s", file, where), file, s_path);
  if (speeds_mm.empty())
    throw FormatError(file, place(s_path), "expected at least one speed, found none");
  require_increasing(speeds_mm, file, s_path, "speeds");
  spectrum.speeds_m_s = to_m(speeds_mm);
  const std::string a_path = member_path(where, "amplitude_m_s2");
  const nlohmann::json& rows = as_array(member(json, "amplitude_m_s2", file, where), file, a_path);
  if (rows.size() != speeds_mm.size()) {
    throw FormatError(file, place(a_path),
                      "expected one row per speed (" + std::to_string(speeds_mm.size()) +
                          "), found " + std::to_string(rows.size()));
  }
  for (std::size_t s = 0; s < rows.size(); ++s) {
    const std::string row_path = element_path(a_path, s);
    std::vector<double> row =
        as_number_array_in(rows[s], file, row_path, 0.0, kMaxAmplitude, kAmplitudeRange);
    if (row.size() != spectrum.frequencies_hz.size()) {
      throw FormatError(file, place(row_path),
                        "expected " + std::to_string(spectrum.frequencies_hz.size()) +
                            " values (one per frequency), found " + std::to_string(row.size()));
    }
    spectrum.amplitude_m_s2.push_back(std::move(row));
  }
  return spectrum;
}

Catalog read_catalog(const std::filesystem::path& file) {
  return catalog_from(parse_file(file), file);
}

std::string catalog_text(const Catalog& catalog, const std::filesystem::path& file,
                         JsonLayout layout) {
  const nlohmann::json json = catalog_json(catalog);
  catalog_from(json, file);  // the same checks as reading, so a written catalog always reads back
  return json_text(json, file, layout == JsonLayout::indented ? 2 : -1);
}

Catalog parse_catalog(const std::string& text, const std::filesystem::path& file) {
  return catalog_from(json_fields::parse_text(text, file), file);
}

void write_catalog(const std::filesystem::path& file, const Catalog& catalog, JsonLayout layout) {
  write_file_atomically(file, catalog_text(catalog, file, layout));
}

}  // namespace nibrig::model::io
