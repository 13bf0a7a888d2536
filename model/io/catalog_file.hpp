// The tool catalog: every tool and surface we know, and for each measured or predicted pairing its
// physical descriptors (friction coefficient, velocity-binned vibration spectrum and its perceptual
// summaries) with where each number came from. Stored as JSON; see write_catalog for the layout.
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "model/io/velocity_spectrum.hpp"

namespace nibrig::model::io {

struct Provenance {
  std::string source;  // a file or a citation
  std::string method;  // how the number was obtained
};

struct ToolEntry {
  std::string id, name;
  // real | printed | commercial | predicted (and "unknown", which model/catalog gives ids it does
  // not recognise)
  std::string kind;
  std::string material;
  std::optional<double> tip_diameter_m;  // "tip_diameter_mm" in the file
};

struct SurfaceEntry {
  std::string id, name;
};

struct FrictionDescriptor {
  double mu = 0.0;  // Coulomb coefficient, key "mu"
  double mu_ci_low = 0.0, mu_ci_high = 0.0;
  std::size_t samples = 0;
  std::vector<double> speeds_m_s;   // "speeds_mm_s" in the file
  std::vector<double> mu_by_speed;  // one per speed
  Provenance provenance;
};

struct VibrationDescriptor {
  VelocitySpectrum spectrum;  // its keys sit directly in the "vibration" object
  double weighted_mean = 0.0, weighted_power = 0.0;
  std::map<int, std::vector<double>> band_energies;  // k -> k uniform band energies
  std::string threshold_curve;  // which detection-threshold curve weighted the spectrum
  Provenance provenance;
};

struct Pairing {
  std::string tool, surface;  // ids from Catalog::tools and Catalog::surfaces
  std::optional<FrictionDescriptor> friction;
  std::optional<VibrationDescriptor> vibration;
};

struct Catalog {
  std::string citation;
  std::vector<ToolEntry> tools;
  std::vector<SurfaceEntry> surfaces;
  std::vector<Pairing> pairings;
  std::vector<std::string> notes;
};

// Reads and validates a catalog; errors name the JSON path, e.g.
// "catalog.json field 'pairings[3].vibration.amplitude_m_s2[2]': expected 12 values ...".
Catalog read_catalog(const std::filesystem::path& file);

// Layout: {"format": "nibrig-catalog", "version": 1, "citation", "tools": [{"id", "name", "kind",
// "material", "tip_diameter_mm"?}], "surfaces": [{"id", "name"}], "pairings": [{"tool", "surface",
// "friction"?: {"mu", "mu_ci_low", "mu_ci_high", "samples", "speeds_mm_s", "mu_by_speed",
// "provenance": {"source", "method"}}, "vibration"?: {"frequencies_hz", "speeds_mm_s",
// "amplitude_m_s2", "weighted_mean", "weighted_power", "band_energies": {"<k>": [k values]},
// "threshold_curve", "provenance"}}], "notes": [...]}.
// Validates first (FormatError naming `file` and the JSON path), then writes through a temporary
// file and a rename so that a reader never sees half a catalog. Indented for people by default;
// JsonLayout::compact writes one line (a bundled catalog is a third of the size).
enum class JsonLayout { indented, compact };
void write_catalog(const std::filesystem::path& file, const Catalog& catalog,
                   JsonLayout layout = JsonLayout::indented);
// The file's text and its reading from text, for a catalog kept in memory (a pickled one): the same
// checks, `file` naming the text in errors.
std::string catalog_text(const Catalog& catalog, const std::filesystem::path& file,
                         JsonLayout layout = JsonLayout::compact);
Catalog parse_catalog(const std::string& text, const std::filesystem::path& file);

// The spectrum as {"frequencies_hz": [...], "speeds_mm_s": [...], "amplitude_m_s2": [[...] per
// speed]}.
nlohmann::json to_json(const VelocitySpectrum& spectrum);

// Reads those three keys from `json` (an object found at JSON path `where` in `file`) and checks
// them: one amplitude row per speed, one value per frequency, all finite, amplitudes >= 0,
// frequencies and speeds >= 0 and strictly increasing.
VelocitySpectrum velocity_spectrum_from_json(const nlohmann::json& json,
                                             const std::filesystem::path& file,
                                             const std::string& where);

}  // namespace nibrig::model::io
