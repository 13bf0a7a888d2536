#include "playback/actuator_store.hpp"

#include <stdexcept>

#include "model/io/user_store.hpp"

namespace nibrig::playback {

std::filesystem::path actuator_folder() { return model::io::user_store_folder("NIBRIG_ACTUATORS", "actuators"); }

std::filesystem::path actuator_path(const std::string& name) {
  return model::io::user_store_file(actuator_folder(), name, "actuator");
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
