#include "model/mechanics/lab_materials.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <mutex>
#include <set>
#include <stdexcept>
#include <system_error>

#include "model/io/atomic_file.hpp"
#include "model/io/format_error.hpp"
#include "model/io/job_files.hpp"
#include "model/io/json_fields.hpp"
#include "model/io/user_store.hpp"

namespace nibrig::model::mechanics {
namespace {

bool same_lab_name(const std::string& a, const std::string& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](unsigned char x, unsigned char y) {
    return std::tolower(x) == std::tolower(y);
  });
}

bool table_has(const MaterialTable& table, const std::string& name) {
  return std::any_of(table.materials().begin(), table.materials().end(),
                     [&](const Material& m) { return same_lab_name(m.name, name); });
}

nlohmann::json material_entry(const Material& m) {
  nlohmann::json j{{"name", m.name},
                   {"youngs_modulus", m.youngs_modulus},
                   {"poisson_ratio", m.poisson_ratio},
                   {"density", m.density}};
  if (m.damping)
    j["rayleigh_mass"] = m.damping->mass, j["rayleigh_stiffness"] = m.damping->stiffness;
  j["basis"] = m.basis;
  j["source"] = m.source;
  return j;
}

std::vector<std::filesystem::path> lab_material_files(const std::filesystem::path& folder) {
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error)) return {};
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error))
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

// Why a lab file was left out, naming it (a format error names it already).
std::string left_out(const std::filesystem::path& file, const std::string& why) {
  return why.find(file.string()) == std::string::npos ? file.string() + ": " + why : why;
}

// A command reads the table more than once; a person needs to hear of a broken file once.
void warn_once(const std::filesystem::path& file, const std::string& why) {
  static std::mutex mutex;
  static std::set<std::string> warned;
  std::lock_guard lock(mutex);
  if (warned.insert(file.string()).second)
    spdlog::warn("lab material left out: {}", left_out(file, why));
}

}  // namespace

std::filesystem::path lab_materials_folder() {
  return io::user_store_folder("NIBRIG_MATERIALS", "materials");
}

std::filesystem::path lab_material_file(const std::string& name) {
  return io::user_store_file(lab_materials_folder(), name, "material");
}

Material read_lab_material_file(const std::filesystem::path& file,
                                const std::filesystem::path& folder) {
  const nlohmann::json root = io::json_fields::parse_file(file);
  const MaterialTable one = material_table_from_json(root, file);
  if (one.materials().size() != 1)
    throw io::FormatError(file, "field 'materials'",
                          "a lab material's file holds exactly one material, found " +
                              std::to_string(one.materials().size()));
  Material m = one.materials().front();
  // The file name is how the lab finds it again: a file renamed by hand would hide its material.
  if (io::user_store_file(folder, m.name, "material").filename() != file.filename())
    throw io::FormatError(file, "field 'materials[0].name'",
                          "'" + m.name + "' belongs in " +
                              io::user_store_file(folder, m.name, "material").filename().string());
  if (root.contains("calibration") && root["calibration"].is_object()) {
    const auto& calibration = root["calibration"];
    const auto number = [&](const char* key) -> std::optional<double> {
      if (!calibration.contains(key)) return std::nullopt;
      const auto& v = calibration[key];
      if (!v.is_number() || !std::isfinite(v.get<double>()) || v.get<double>() < 0)
        throw io::FormatError(file, std::string("field 'calibration.") + key + "'",
                              "expected a standard deviation, a finite number >= 0");
      return v.get<double>();
    };
    m.youngs_modulus_sd = number("youngs_modulus_sd");
    m.rayleigh_stiffness_sd = number("rayleigh_stiffness_sd");
    if (calibration.contains("modulus_damping_correlation")) {
      const auto& r = calibration["modulus_damping_correlation"];
      if (!r.is_number() || !(r.get<double>() >= -1 && r.get<double>() <= 1))
        throw io::FormatError(file, "field 'calibration.modulus_damping_correlation'",
                              "expected a number from -1 to 1");
      m.modulus_damping_correlation = r.get<double>();
    }
    if (calibration.contains("printed_as")) {
      if (!calibration["printed_as"].is_string())
        throw io::FormatError(file, "field 'calibration.printed_as'",
                              "expected the name of the material printed");
      m.printed_as = calibration["printed_as"].get<std::string>();
    }
  }
  return m;
}

std::vector<Material> read_lab_materials(const std::filesystem::path& folder) {
  std::vector<Material> out;
  for (const auto& file : lab_material_files(folder))
    out.push_back(read_lab_material_file(file, folder));
  return out;
}

MaterialTable with_lab_materials(const MaterialTable& table, const std::filesystem::path& folder) {
  std::vector<Material> all = table.materials();
  std::string skipped;
  for (const auto& file : lab_material_files(folder)) {
    try {
      Material m = read_lab_material_file(file, folder);
      if (!table_has(table, m.name)) all.push_back(std::move(m));
    } catch (const std::exception& e) {  // io::FormatError, or a file that vanished meanwhile
      skipped += "; skipped " + left_out(file, e.what());
      warn_once(file, e.what());
    }
  }
  MaterialTable out(std::move(all));
  std::vector<std::string> places = table.looked_in();
  places.push_back("the lab's materials in " + folder.string() + skipped);
  out.set_looked_in(std::move(places));
  return out;
}

void add_lab_materials(io::CacheKey& key, const std::filesystem::path& folder) {
  const auto files = lab_material_files(folder);
  key.add(static_cast<std::int64_t>(files.size()));
  for (const auto& file : files) {
    key.add(file.filename().string());
    try {
      key.add_file(file);
    } catch (const std::runtime_error&) {  // gone meanwhile: as if never there
      key.add(std::string_view("unreadable"));
    }
  }
}

void check_lab_material_name(const std::string& name, const MaterialTable& bundled, bool replace) {
  if (name.empty()) throw std::invalid_argument("a lab material needs a name");
  const auto file = lab_material_file(name);
  if (table_has(bundled, name))
    throw std::invalid_argument("material name '" + name +
                                "' is a bundled material's: give the lab's own a distinct name "
                                "(e.g. '" +
                                name +
                                "-lab'); the bundled table is never "
                                "written over");
  std::error_code error;
  if (!replace && std::filesystem::exists(file, error))
    throw std::invalid_argument("the lab already has a material '" + name + "' (" + file.string() +
                                "): give another name, or replace it on purpose");
}

std::filesystem::path save_lab_material(const Material& material, const nlohmann::json& calibration,
                                        const MaterialTable& bundled, bool replace) {
  validate(material);
  check_lab_material_name(material.name, bundled, replace);
  const auto file = lab_material_file(material.name);
  Material saved = material;
  saved.basis = "fitted";
  nlohmann::json root{{"format", "nibrig-materials"},
                      {"version", 1},
                      {"comment", "A lab's own material, fitted by nibrig material calibrate."},
                      {"materials", nlohmann::json::array({material_entry(saved)})},
                      {"calibration", calibration}};
  std::filesystem::create_directories(file.parent_path());
  // Every command reads the lab's files with the table; replacing one was asked for.
  if (replace) io::release_input(file);
  io::write_file_atomically(file, root.dump(2) + "\n");
  return file;
}

}  // namespace nibrig::model::mechanics
