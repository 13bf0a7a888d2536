// A tool on a surface as the bundled catalog and stylus make it (model::design::ToolSounds), meshed
// once per test binary: the rig tests use a few of them many times.
#pragma once

#include <map>
#include <string>
#include <utility>

#include "model/design/tool_sound.hpp"

namespace nibrig::rig::testing {

inline const model::design::ToolSound& bundled_sound(const std::string& tool, const std::string& surface) {
  static model::design::ToolSounds sounds({});
  static std::map<std::pair<std::string, std::string>, model::design::ToolSound> made;
  const auto key = std::make_pair(tool, surface);
  auto it = made.find(key);
  if (it == made.end()) it = made.emplace(key, sounds.sound(tool, surface)).first;
  return it->second;
}

}  // namespace nibrig::rig::testing
