#include "playback/actuator_store.hpp"

#include <cctype>
#include <cstdlib>
#include <stdexcept>

namespace nibrig::playback {

std::filesystem::path actuator_folder() {
  if (const char* d = std::getenv("NIBRIG_ACTUATORS"); d && *d) return d;
  if (const char* d = std::getenv("XDG_DATA_HOME"); d && *d)
    return std::filesystem::path(d) / "nibrig" / "actuators";
  const char* home = std::getenv("HOME");
  return std::filesystem::path(home && *home ? home : ".") / ".local" / "share" / "nibrig" /
         "actuators";
}

std::filesystem::path actuator_path(const std::string& name) {
  std::string safe = name;
  for (char& c : safe)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
  if (safe.empty() || safe == "." || safe == "..") safe = "actuator";
  return actuator_folder() / (safe + ".json");
}

std::filesystem::path find_actuator(const std::string& name_or_file) {
  if (std::filesystem::is_regular_file(name_or_file)) return name_or_file;
  const auto stored = actuator_path(name_or_file);
  if (std::filesystem::is_regular_file(stored)) return stored;
  std::string known;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(actuator_folder(), error))
    if (entry.path().extension() == ".json")
      known += (known.empty() ? "" : ", ") + entry.path().stem().string();
  throw std::invalid_argument("no actuator file '" + name_or_file + "' and no calibration named so in " +
                              actuator_folder().string() +
                              (known.empty() ? " (none stored yet: run `nibrig calibrate`)"
                                             : " (stored: " + known + ")"));
}

}  // namespace nibrig::playback
