// session.json of a rig session (rig_session.hpp): conversion between RigSessionInfo and JSON, and the
// checks both the writer (before recording) and the reader (after) apply to it.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "model/io/rig_session.hpp"

namespace nibrig::model::io::session_json {

inline constexpr const char* kFormat = "nibrig-session";
inline constexpr int kVersion = 1;

// Stream names as used in session.json's "frames" and in messages, in the writer's order.
inline constexpr std::array<const char*, 4> kStreams = {"acceleration", "speed", "normal_force",
                                                        "tangential_force"};

struct Problem {
  std::string field;  // JSON path
  std::string what;
};

// The first thing wrong with `info`, if any (empty tool, rates that are not whole positive hertz,
// non-positive calibration factors, ...).
std::optional<Problem> check(const RigSessionInfo& info);

// The rate session.json declares for stream k of kStreams.
double rate_of(const RigSessionInfo& info, std::size_t stream);

// frames: written by finish(), one count per stream; absent while recording.
nlohmann::json to_json(const RigSessionInfo& info, const std::array<std::int64_t, 4>* frames);

struct Parsed {
  RigSessionInfo info;
  std::optional<std::array<std::int64_t, 4>> frames;
};

// Validates everything; FormatError names session.json and the field.
Parsed from_json(const nlohmann::json& json, const std::filesystem::path& file);

}  // namespace nibrig::model::io::session_json
