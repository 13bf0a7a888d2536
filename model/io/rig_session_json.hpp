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

// The range of calibration.accelerometer_m_s2_per_unit, the accelerometer's m/s² at its stream's full
// scale (`calibrate --accelerometer`): 0.001 g to 100 000 g. Held here, where both the session's
// reader and the rig's requests (rig/rig_request.hpp, whose --accelerometer checks the same) see
// it: a positive 1e-320 made every sample a subnormal nothing and 1e308 an overflow.
inline constexpr double kLeastAccelerometerM_s2PerUnit = 0.01;
inline constexpr double kMostAccelerometerM_s2PerUnit = 1e6;

struct Problem {
  std::string field;  // JSON path
  std::string what;
};

// The first thing wrong with `info`, if any (empty tool, rates that are not whole positive hertz,
// non-positive calibration factors, an accelerometer scale outside the range above, ...).
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
