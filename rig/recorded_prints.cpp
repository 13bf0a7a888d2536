#include "rig/recorded_prints.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "model/catalog/tool_names.hpp"
#include "model/io/paper_friction.hpp"
#include "model/io/paper_vibration.hpp"

namespace nibrig::rig {

namespace fs = std::filesystem;

namespace {

// A print's key: material and tip in whole micrometres, the precision of the file names.
using PrintKey = std::pair<std::string, long>;

PrintKey key_of(const std::string& material, double tip_m) {
  return {material, std::lround(tip_m * 1e6)};
}

}  // namespace

std::vector<RecordedPrint> find_recorded_prints(const fs::path& folder, const std::string& surface,
                                                const std::vector<std::string>& materials) {
  if (!fs::is_directory(folder))
    throw std::invalid_argument(folder.string() + ": not a folder of recorded prints");
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(folder))
    if (entry.is_regular_file()) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  const auto wanted = [&](const std::string& material) {
    return std::find(materials.begin(), materials.end(), material) != materials.end();
  };
  std::map<PrintKey, fs::path> vibration;
  std::map<PrintKey, std::pair<int, fs::path>> friction;
  for (const auto& file : files) {
    if (model::io::is_paper_vibration_file(file)) {
      model::io::VibrationFileName name;
      try {
        name = model::io::parse_vibration_file_name(file);
      } catch (const std::exception&) {
        continue;  // not one of the paper's names: not a recorded print
      }
      if (name.surface != surface || !wanted(name.material) || !name.tip_diameter_m ||
          !(name.variant.empty() || name.variant == "plain"))
        continue;
      vibration.emplace(key_of(name.material, *name.tip_diameter_m), file);
      continue;
    }
    model::io::FrictionFileName name;
    try {
      name = model::io::parse_friction_file_name(file);
    } catch (const std::exception&) {
      continue;
    }
    if (name.surface != surface) continue;
    const auto tool = model::catalog::describe_tool(name.tool);
    if (tool.kind != "printed" || !wanted(tool.material) || !tool.tip_diameter_m ||
        tool.id.find('_') != std::string::npos)
      continue;
    const PrintKey key = key_of(tool.material, *tool.tip_diameter_m);
    const auto it = friction.find(key);
    if (it == friction.end() || name.repetition < it->second.first)
      friction[key] = {name.repetition, file};
  }
  std::vector<RecordedPrint> out;
  for (const auto& material : materials)
    for (const auto& [key, file] : vibration) {
      if (key.first != material) continue;
      const auto f = friction.find(key);
      if (f == friction.end()) continue;
      RecordedPrint p;
      p.design.mix = {{material, 1.0}};
      p.design.tip_diameter_m = static_cast<double>(key.second) * 1e-6;
      p.vibration = file;
      p.friction = f->second.second;
      out.push_back(std::move(p));
    }
  if (out.empty()) {
    std::string names;
    for (const auto& m : materials) names += (names.empty() ? "" : " or ") + m;
    throw std::invalid_argument(
        folder.string() + ": no print of " + names + " recorded on " + surface +
        " with both its recordings (expected arm_<material>_<tip>_" + surface +
        ".csv[.gz] and <material><tip>_" + surface + "_<load>N_<lever>_<rep>.csv[.gz])");
  }
  return out;
}

std::vector<model::design::DesignPoint> designs_of(const std::vector<RecordedPrint>& prints) {
  std::vector<model::design::DesignPoint> out;
  for (const auto& p : prints) out.push_back(p.design);
  return out;
}

}  // namespace nibrig::rig
