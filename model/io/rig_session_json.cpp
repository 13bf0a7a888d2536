#include "model/io/rig_session_json.hpp"

#include <cmath>
#include <sstream>

#include "model/io/format_error.hpp"
#include "model/io/json_fields.hpp"
#include "model/io/paper_friction.hpp"

namespace nibrig::model::io::session_json {

namespace {

// libsndfile keeps the rate in an int; anything near that is not a real sensor rate anyway.
constexpr double kHighestRate_hz = 10'000'000.0;

std::optional<Problem> check_rate(double rate, const char* field) {
  if (!std::isfinite(rate) || rate < 1.0 || rate > kHighestRate_hz || std::floor(rate) != rate) {
    return Problem{field, "expected a whole number of hertz in [1, 10000000], found " +
                              nlohmann::json(rate).dump()};
  }
  return std::nullopt;
}

std::optional<Problem> check_positive(double value, const char* field) {
  if (!std::isfinite(value) || value <= 0.0) {
    return Problem{field, "expected a positive number, found " + nlohmann::json(value).dump()};
  }
  return std::nullopt;
}

}  // namespace

std::optional<Problem> check(const RigSessionInfo& info) {
  if (info.tool.empty()) return Problem{"tool", "expected a tool id, found an empty string"};
  if (info.surface.empty())
    return Problem{"surface", "expected a surface id, found an empty string"};
  // 0: no load (a session not about friction); else the range a recording's load is held to
  // (paper_friction.hpp): a load of 1e-320 N divided the tangential force into infinities.
  if (const double load = info.normal_load_N;
      !(load == 0.0 || (load >= kLightestFrictionLoadN && load <= kHeaviestFrictionLoadN))) {
    std::ostringstream what;
    what << "expected a load in newtons, 0 or " << kLightestFrictionLoadN << " to " << kHeaviestFrictionLoadN
         << ", found " << nlohmann::json(load).dump();
    return Problem{"normal_load_N", what.str()};
  }
  if (auto p = check_rate(info.acceleration_rate_hz, "acceleration_rate_hz")) return p;
  if (auto p = check_rate(info.speed_rate_hz, "speed_rate_hz")) return p;
  if (auto p = check_rate(info.force_rate_hz, "force_rate_hz")) return p;
  if (const double a = info.calibration.accelerometer_m_s2_per_unit;
      !(a >= kLeastAccelerometerM_s2PerUnit && a <= kMostAccelerometerM_s2PerUnit)) {
    std::ostringstream what;
    what << "expected an accelerometer's m/s² at full scale, " << kLeastAccelerometerM_s2PerUnit << " to "
         << kMostAccelerometerM_s2PerUnit << ", found " << nlohmann::json(a).dump();
    return Problem{"calibration.accelerometer_m_s2_per_unit", what.str()};
  }
  if (auto p =
          check_positive(info.calibration.force_counts_per_N, "calibration.force_counts_per_N")) {
    return p;
  }
  if (auto p = check_positive(info.calibration.lever_factor, "calibration.lever_factor")) return p;
  if (info.profile_time_s.size() != info.profile_speed_m_s.size()) {
    return Problem{"speed_profile_points", "expected as many speeds as times, found " +
                                               std::to_string(info.profile_speed_m_s.size()) +
                                               " and " + std::to_string(info.profile_time_s.size())};
  }
  for (std::size_t i = 0; i < info.profile_time_s.size(); ++i) {
    const double t = info.profile_time_s[i], v = info.profile_speed_m_s[i];
    if (!std::isfinite(t) || !std::isfinite(v) || v < 0.0 ||
        (i > 0 && t < info.profile_time_s[i - 1]) || (i == 0 && t != 0.0)) {
      return Problem{"speed_profile_points",
                     "point " + std::to_string(i + 1) +
                         ": expected times from 0 that never decrease and speeds >= 0"};
    }
  }
  return std::nullopt;
}

double rate_of(const RigSessionInfo& info, std::size_t stream) {
  switch (stream) {
    case 0:
      return info.acceleration_rate_hz;
    case 1:
      return info.speed_rate_hz;
    default:
      return info.force_rate_hz;
  }
}

nlohmann::json to_json(const RigSessionInfo& info, const std::array<std::int64_t, 4>* frames) {
  nlohmann::json json = {
      {"format", kFormat},
      {"version", kVersion},
      {"tool", info.tool},
      {"surface", info.surface},
      {"normal_load_N", info.normal_load_N},
      {"acceleration_rate_hz", info.acceleration_rate_hz},
      {"speed_rate_hz", info.speed_rate_hz},
      {"force_rate_hz", info.force_rate_hz},
      {"units", info.units},
      {"calibration",
       {{"accelerometer_m_s2_per_unit", info.calibration.accelerometer_m_s2_per_unit},
        {"force_counts_per_N", info.calibration.force_counts_per_N},
        {"lever_factor", info.calibration.lever_factor}}},
      {"speed_profile", info.speed_profile},
      {"notes", info.notes},
      {"created_utc", info.created_utc},
  };
  if (!info.profile_time_s.empty()) {
    std::vector<double> mm_s;
    for (double v : info.profile_speed_m_s) mm_s.push_back(v * 1e3);
    json["speed_profile_points"] = {{"time_s", info.profile_time_s}, {"speed_mm_s", mm_s}};
  }
  if (info.capture) {
    const CaptureRecord& c = *info.capture;
    json["capture"] = {{"rig", c.rig},
                       {"seconds", c.seconds},
                       {"frames", c.frames},
                       {"dropped_frames", c.dropped_frames},
                       {"saturated_frames", c.saturated_frames},
                       {"fault_frames", c.fault_frames},
                       {"alignment_error_ms", c.alignment_error_ms},
                       {"ended_because", c.ended_because}};
  }
  if (frames != nullptr) {
    nlohmann::json counts = nlohmann::json::object();
    for (std::size_t k = 0; k < kStreams.size(); ++k) counts[kStreams[k]] = (*frames)[k];
    json["frames"] = counts;
  }
  return json;
}

Parsed from_json(const nlohmann::json& json, const std::filesystem::path& file) {
  using namespace json_fields;
  as_object(json, file, "");
  check_format_and_version(json, file, kFormat, kVersion);
  Parsed parsed;
  RigSessionInfo& info = parsed.info;
  info.tool = string_member(json, "tool", file, "");
  info.surface = string_member(json, "surface", file, "");
  info.normal_load_N = number_member(json, "normal_load_N", file, "");
  info.acceleration_rate_hz = number_member(json, "acceleration_rate_hz", file, "");
  info.speed_rate_hz = number_member(json, "speed_rate_hz", file, "");
  info.force_rate_hz = number_member(json, "force_rate_hz", file, "");
  const nlohmann::json& units = as_object(member(json, "units", file, ""), file, "units");
  for (const auto& [key, value] : units.items()) {
    info.units[key] = as_string(value, file, member_path("units", key));
  }
  const nlohmann::json& calibration = member(json, "calibration", file, "");
  info.calibration.accelerometer_m_s2_per_unit =
      number_member(calibration, "accelerometer_m_s2_per_unit", file, "calibration");
  info.calibration.force_counts_per_N =
      number_member(calibration, "force_counts_per_N", file, "calibration");
  info.calibration.lever_factor = number_member(calibration, "lever_factor", file, "calibration");
  info.speed_profile = string_member(json, "speed_profile", file, "");
  info.notes = string_member(json, "notes", file, "");
  info.created_utc = string_member(json, "created_utc", file, "");
  if (auto problem = check(info)) throw FormatError(file, place(problem->field), problem->what);
  if (const auto it = json.find("speed_profile_points"); it != json.end()) {
    as_object(*it, file, "speed_profile_points");
    info.profile_time_s = as_number_array(member(*it, "time_s", file, "speed_profile_points"), file,
                                          "speed_profile_points.time_s");
    info.profile_speed_m_s = as_number_array(
        member(*it, "speed_mm_s", file, "speed_profile_points"), file, "speed_profile_points.speed_mm_s");
    for (double& v : info.profile_speed_m_s) v *= 1e-3;
    if (auto problem = check(info)) throw FormatError(file, place(problem->field), problem->what);
  }
  if (const auto it = json.find("capture"); it != json.end()) {
    as_object(*it, file, "capture");
    CaptureRecord c;
    const auto count = [&](const char* key) {
      return static_cast<std::uint64_t>(
          as_integer(member(*it, key, file, "capture"), file, member_path("capture", key), 0,
                     INT64_MAX));
    };
    c.rig = string_member(*it, "rig", file, "capture");
    c.seconds = number_member(*it, "seconds", file, "capture");
    c.frames = count("frames");
    c.dropped_frames = count("dropped_frames");
    c.saturated_frames = count("saturated_frames");
    c.fault_frames = count("fault_frames");
    c.alignment_error_ms = number_member(*it, "alignment_error_ms", file, "capture");
    c.ended_because = string_member(*it, "ended_because", file, "capture");
    info.capture = c;
  }

  if (const auto it = json.find("frames"); it != json.end()) {
    as_object(*it, file, "frames");
    std::array<std::int64_t, 4> frames{};
    for (std::size_t k = 0; k < kStreams.size(); ++k) {
      frames[k] = as_integer(member(*it, kStreams[k], file, "frames"), file,
                             member_path("frames", kStreams[k]), 0, INT64_MAX);
    }
    parsed.frames = frames;
  }
  return parsed;
}

}  // namespace nibrig::model::io::session_json
