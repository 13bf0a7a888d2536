// Where actuator calibrations live, one file per actuator, so that a rig with several actuators
// (or several rigs) keeps each one's inverse filter under its name: $NIBRIG_ACTUATORS, else
// $XDG_DATA_HOME/nibrig/actuators, else ~/.local/share/nibrig/actuators.
#pragma once

#include <filesystem>
#include <string>

namespace nibrig::playback {

std::filesystem::path actuator_folder();

// <folder>/<name>.json, the name made safe for a file name (anything but letters, digits, '-',
// '_' and '.' becomes '_').
std::filesystem::path actuator_path(const std::string& name);

// `name_or_file` as given when it is an existing file, else the stored actuator of that name.
// Throws std::invalid_argument listing the stored actuators when neither exists.
std::filesystem::path find_actuator(const std::string& name_or_file);

}  // namespace nibrig::playback
