#include "playback/actuator_file.hpp"

#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/io/atomic_file.hpp"
#include "model/io/format_error.hpp"
#include "model/io/json_fields.hpp"
#include "model/io/finite_output.hpp"

namespace nibrig::playback {
namespace {

namespace jf = model::io::json_fields;
using model::io::FormatError;
using nlohmann::json;

constexpr const char* kFormat = "nibrig-actuator";
constexpr long long kVersion = 1;

// Reading context: the file, for every error.
struct Reader {
  const std::filesystem::path& file;

  const json& member(const json& object, const std::string& key, const std::string& parent) const {
    return jf::member(object, key, file, parent);
  }
  double number(const json& object, const std::string& key, const std::string& parent) const {
    return jf::number_member(object, key, file, parent);
  }
  double positive(const json& object, const std::string& key, const std::string& parent) const {
    const double value = number(object, key, parent);
    if (!(value > 0)) fail(jf::member_path(parent, key), "expected a positive number");
    return value;
  }
  std::vector<double> numbers(const json& object, const std::string& key,
                              const std::string& parent) const {
    return jf::as_number_array(member(object, key, parent), file, jf::member_path(parent, key));
  }
  [[noreturn]] void fail(const std::string& path, const std::string& problem) const {
    throw FormatError(file, jf::place(path), problem);
  }
};

json sweep_json(const SineSweepSettings& s) {
  return {{"sample_rate_hz", s.sample_rate_hz},
          {"start_hz", s.start_hz},
          {"end_hz", s.end_hz},
          {"duration_s", s.duration_s},
          {"level", s.level},
          {"fade_s", s.fade_s},
          {"silence_s", s.silence_s},
          {"repetitions", s.repetitions}};
}

SineSweepSettings read_sweep(const Reader& r, const json& root) {
  const json& j = r.member(root, "sweep", "");
  SineSweepSettings s;
  s.sample_rate_hz = r.number(j, "sample_rate_hz", "sweep");
  s.start_hz = r.number(j, "start_hz", "sweep");
  s.end_hz = r.number(j, "end_hz", "sweep");
  s.duration_s = r.number(j, "duration_s", "sweep");
  s.level = r.number(j, "level", "sweep");
  s.fade_s = r.number(j, "fade_s", "sweep");
  s.silence_s = r.number(j, "silence_s", "sweep");
  s.repetitions = static_cast<int>(
      jf::as_integer(r.member(j, "repetitions", "sweep"), r.file, "sweep.repetitions", 1, 100));
  try {
    validate(s);
  } catch (const std::invalid_argument& error) {
    r.fail("sweep", std::string("inconsistent settings: ") + error.what());
  }
  return s;
}

FrequencyResponse read_response(const Reader& r, const json& root) {
  const json& j = r.member(root, "response", "");
  const std::vector<double> f = r.numbers(j, "frequencies_hz", "response");
  const std::vector<double> magnitude = r.numbers(j, "magnitude", "response");
  const std::vector<double> phase = r.numbers(j, "phase_rad", "response");
  if (f.size() < 2) r.fail("response.frequencies_hz", "expected at least two frequencies");
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (!(f[i] > 0) || (i > 0 && !(f[i] > f[i - 1])))
      r.fail(jf::element_path("response.frequencies_hz", i),
             "expected positive frequencies in increasing order");
  }
  if (magnitude.size() != f.size())
    r.fail("response.magnitude", "expected " + std::to_string(f.size()) +
                                     " values (one per frequency), found " +
                                     std::to_string(magnitude.size()));
  if (phase.size() != f.size())
    r.fail("response.phase_rad", "expected " + std::to_string(f.size()) +
                                     " values (one per frequency), found " +
                                     std::to_string(phase.size()));
  FrequencyResponse out;
  out.frequencies_hz = f;
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (!(magnitude[i] > 0))
      r.fail(jf::element_path("response.magnitude", i), "expected a positive magnitude");
    out.values.push_back(std::polar(magnitude[i], phase[i]));
  }
  return out;
}

}  // namespace

void write_actuator_file(const std::filesystem::path& file, const ActuatorCalibration& c) {
  if (c.response.frequencies_hz.empty() ||
      c.response.values.size() != c.response.frequencies_hz.size())
    throw std::invalid_argument("actuator file: the calibration has no (or a mismatched) response");
  if (c.filter.taps.empty()) throw std::invalid_argument("actuator file: the filter has no taps");
  std::vector<double> magnitude, phase;
  for (const auto& v : c.response.values) {
    magnitude.push_back(std::abs(v));
    phase.push_back(std::arg(v));
  }
  json limited = json::array();
  for (const FrequencyRange& range : c.filter.boost_limited)
    limited.push_back({range.low_hz, range.high_hz});
  const json j = {
      {"format", kFormat},
      {"version", kVersion},
      {"name", c.name},
      {"created", c.created},
      {"sweep", sweep_json(c.sweep)},
      {"delay_s", c.delay_s},
      {"response",
       {{"frequencies_hz", c.response.frequencies_hz},
        {"magnitude", magnitude},
        {"phase_rad", phase}}},
      {"band_hz", {c.design.band_low_hz, c.design.band_high_hz}},
      {"regularisation",
       {{"in_band", c.design.in_band_regularisation},
        {"low_corner_hz", c.design.low_corner_hz},
        {"high_corner_hz", c.design.high_corner_hz},
        {"max_boost_db", c.design.max_boost_db}}},
      {"filter", {{"sample_rate_hz", c.filter.sample_rate_hz}, {"taps", c.filter.taps}}},
      {"flatness_db",
       {{"max_deviation", c.filter.max_deviation_db},
        {"rms_deviation", c.filter.rms_deviation_db}}},
      {"boost", {{"max_db", c.filter.max_boost_db}, {"limited_hz", limited}}},
      {"group_delay_100hz_s", c.filter.group_delay_100hz_s},
  };
  model::io::write_file_atomically(file, model::io::json_text(j, file));
}

ActuatorCalibration read_actuator_file(const std::filesystem::path& file) {
  const json root = jf::parse_file(file);
  const Reader r{file};
  jf::as_object(root, file, "");
  jf::check_format_and_version(root, file, kFormat, kVersion);
  ActuatorCalibration c;
  c.name = jf::string_member(root, "name", file, "");
  c.created = jf::string_member(root, "created", file, "");
  c.sweep = read_sweep(r, root);
  c.delay_s = r.number(root, "delay_s", "");
  if (c.delay_s < 0) r.fail("delay_s", "expected a delay of 0 s or more");
  c.response = read_response(r, root);

  const std::vector<double> band = r.numbers(root, "band_hz", "");
  if (band.size() != 2 || !(band[0] > 0) || !(band[1] > band[0]))
    r.fail("band_hz", "expected [low, high] with 0 < low < high");
  c.design.band_low_hz = band[0];
  c.design.band_high_hz = band[1];
  const json& reg = r.member(root, "regularisation", "");
  c.design.in_band_regularisation = r.positive(reg, "in_band", "regularisation");
  c.design.low_corner_hz = r.positive(reg, "low_corner_hz", "regularisation");
  c.design.high_corner_hz = r.positive(reg, "high_corner_hz", "regularisation");
  c.design.max_boost_db = r.positive(reg, "max_boost_db", "regularisation");

  const json& filter = r.member(root, "filter", "");
  c.filter.sample_rate_hz = r.number(filter, "sample_rate_hz", "filter");
  if (!(c.filter.sample_rate_hz >= 2000.0 && c.filter.sample_rate_hz <= 8000.0))
    r.fail("filter.sample_rate_hz", "expected an internal rate of 2000 to 8000 Hz");
  c.filter.taps = r.numbers(filter, "taps", "filter");
  if (c.filter.taps.empty()) r.fail("filter.taps", "expected at least one tap");
  c.design.sample_rate_hz = c.filter.sample_rate_hz;
  c.design.taps = c.filter.taps.size();

  const json& flatness = r.member(root, "flatness_db", "");
  c.filter.max_deviation_db = r.number(flatness, "max_deviation", "flatness_db");
  c.filter.rms_deviation_db = r.number(flatness, "rms_deviation", "flatness_db");
  const json& boost = r.member(root, "boost", "");
  c.filter.max_boost_db = r.number(boost, "max_db", "boost");
  const json& limited =
      jf::as_array(r.member(boost, "limited_hz", "boost"), file, "boost.limited_hz");
  for (std::size_t i = 0; i < limited.size(); ++i) {
    const std::string path = jf::element_path("boost.limited_hz", i);
    const std::vector<double> range = jf::as_number_array(limited[i], file, path);
    if (range.size() != 2 || range[1] < range[0])
      r.fail(path, "expected [low, high] with low ≤ high");
    c.filter.boost_limited.push_back({range[0], range[1]});
  }
  c.filter.group_delay_100hz_s = r.number(root, "group_delay_100hz_s", "");
  return c;
}

InverseFilter redesign_for_rate(const ActuatorCalibration& c, double sample_rate_hz) {
  InverseFilterSettings settings = c.design;
  settings.sample_rate_hz = sample_rate_hz;
  settings.taps = static_cast<std::size_t>(
      std::llround(static_cast<double>(c.design.taps) * sample_rate_hz / c.design.sample_rate_hz));
  return design_inverse_filter(c.response, settings);
}

}  // namespace nibrig::playback
