// Where the things a user measures once and keeps by name live (actuator calibrations, pens'
// pressure curves): one folder per kind, one file per name, so that a lab with several actuators
// or pens keeps each under its own name.
#pragma once

#include <filesystem>
#include <string>

namespace nibrig::model::io {

// $<override_variable> when set, else $XDG_DATA_HOME/nibrig/<kind>, else
// ~/.local/share/nibrig/<kind> (not created here).
std::filesystem::path user_store_folder(const char* override_variable, const std::string& kind);

// <folder>/<name>.json, the name made safe for a file name (anything but letters, digits, '-', '_'
// and '.' becomes '_'; `fallback` for a name left empty or only dots).
std::filesystem::path user_store_file(const std::filesystem::path& folder, const std::string& name,
                                      const std::string& fallback);

}  // namespace nibrig::model::io
