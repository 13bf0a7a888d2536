#include "model/io/paper_vibration.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <stdexcept>

#include "model/io/format_error.hpp"
#include "model/io/text_lines.hpp"

namespace nibrig::model::io {

namespace {

constexpr const char* kVibrationName =
    "arm_<tool>_<surface>, arm_<material>_<tip>_<surface>, arm_plain_<material>_<tip>[_nailN]_"
    "<surface> or arm_penh_<material>_<surface> (.csv or .csv.gz)";
constexpr const char* kVibrationHeader = "time,timestamp,xAccel,yAccel,zAccel,xxx (or blank ,,,,,)";

// Longer steps are pauses between sweeps, not the sample spacing: they are recorded as gaps but
// left out of the rate estimate.
constexpr long long kLongestSampleStep_ms = 100;
// The worst real file loses 0.2 % of its samples to dropped-sample gaps; another device rate
// (500, 1024, 2000 Hz) is far outside 2 %.
constexpr double kVibrationRateTolerance = 0.02;

[[noreturn]] void bad_vibration_name(const std::filesystem::path& file, const std::string& why) {
  throw FormatError(
      file, "", "unparsable file name, expected " + std::string(kVibrationName) + " (" + why + ")");
}

bool is_word(std::string_view text) {
  return !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0;
  });
}

bool is_nail_variant(std::string_view text) {
  return text.size() > 4 && text.substr(0, 4) == "nail" &&
         std::all_of(text.begin() + 4, text.end(),
                     [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; });
}

void set_printed(VibrationFileName& name, const std::filesystem::path& file,
                 std::string_view material, std::string_view tip) {
  if (std::isalpha(static_cast<unsigned char>(material.front())) == 0) {
    bad_vibration_name(file, "a material starts with a letter, found " + in_quotes(material));
  }
  const auto mm = positive_number_in_name(tip);
  if (!mm)
    bad_vibration_name(file, "the tip diameter must be a positive number of mm, found " + in_quotes(tip));
  name.material = std::string(material);
  name.tip_diameter_m = *mm * 1e-3;
  name.tool = std::string(material) + std::string(tip);
}

}  // namespace

bool is_paper_vibration_file(const std::filesystem::path& file) {
  const auto stem = csv_stem(file);
  return stem && stem->size() > 4 && stem->compare(0, 4, "arm_") == 0;
}

VibrationFileName parse_vibration_file_name(const std::filesystem::path& file) {
  const auto stem = csv_stem(file);
  if (!stem) bad_vibration_name(file, "not a .csv or .csv.gz file");
  if (stem->compare(0, 4, "arm_") != 0) bad_vibration_name(file, "the name must start with 'arm_'");
  std::vector<std::string_view> tokens = split_fields(std::string_view(*stem).substr(4), '_');
  for (std::string_view token : tokens) {
    if (!is_word(token))
      bad_vibration_name(file, "parts must be letters and digits, found " + in_quotes(token));
  }
  VibrationFileName name;
  name.surface = std::string(tokens.back());
  const std::size_t n = tokens.size();
  if (tokens.front() == "plain") {
    if (n != 4 && !(n == 5 && is_nail_variant(tokens[3]))) {
      bad_vibration_name(file, "arm_plain_ takes <material>_<tip>[_nailN]_<surface>");
    }
    set_printed(name, file, tokens[1], tokens[2]);
    name.variant = "plain";
    if (n == 5) {
      name.variant = std::string(tokens[3]);
      name.tool += "_" + name.variant;
    }
    return name;
  }
  if (tokens.front() == "penh") {
    if (n != 3) bad_vibration_name(file, "arm_penh_ takes <material>_<surface>");
    if (std::isalpha(static_cast<unsigned char>(tokens[1].front())) == 0) {
      bad_vibration_name(file, "a material starts with a letter, found " + in_quotes(tokens[1]));
    }
    name.material = std::string(tokens[1]);
    name.variant = "penh";
    name.tool = "penh_" + name.material;
    return name;
  }
  if (n == 3) {
    set_printed(name, file, tokens[0], tokens[1]);
    return name;
  }
  if (n == 2) {
    name.tool = std::string(tokens[0]);
    return name;
  }
  bad_vibration_name(file, "found " + std::to_string(n) + " parts after 'arm_'");
}

VibrationRecording read_paper_vibration(const std::filesystem::path& file) {
  return read_paper_vibration(file, parse_vibration_file_name(file));
}

VibrationRecording read_paper_vibration(const std::filesystem::path& file, VibrationFileName name) {
  if (name.tool.empty() || name.surface.empty())
    throw std::invalid_argument(file.string() + ": a recording needs a tool and a surface id");
  VibrationRecording recording;
  recording.name = std::move(name);
  recording.source = file;

  CsvReader csv(file, kVibrationHeader);
  const CsvHeader& header = csv.header();
  std::size_t c_stamp = 1;
  std::size_t c_accel = 2;
  const bool blank_header = std::all_of(header.names().begin(), header.names().end(),
                                        [](const std::string& name) { return name.empty(); });
  if (!blank_header) {
    c_stamp = header.column("timestamp");
    c_accel = header.column("xAccel");
  }
  const std::size_t needed = std::max(c_stamp, c_accel) + 1;

  std::vector<std::string_view> fields;
  long long first_ms = 0;
  long long previous_ms = 0;
  long long steps = 0;         // sample steps up to kLongestSampleStep_ms ...
  long long step_time_ms = 0;  // ... and the time they cover
  while (csv.next(fields)) {
    const std::size_t line = csv.line_number();
    if (csv.cut_off_last_row(fields, needed, recording.warnings)) break;
    csv.require_fields(fields, needed);
    const long long stamp_ms = parse_unix_ms(fields[c_stamp], file, line, "timestamp");
    const double accel_g = parse_number(fields[c_accel], file, line, "xAccel");
    if (std::abs(accel_g) > kLargestPaperAcceleration_g)
      throw FormatError(file, field_place(line, "xAccel"),
                        "expected an acceleration in g of at most " +
                            std::to_string(static_cast<int>(kLargestPaperAcceleration_g)) + ", found " +
                            in_quotes(fields[c_accel]));
    const std::size_t index = recording.acceleration_m_s2.size();
    if (index == 0) {
      first_ms = stamp_ms;
    } else {
      if (stamp_ms < previous_ms) {
        throw FormatError(file, field_place(line, "timestamp"),
                          "expected time to increase, found " + std::to_string(stamp_ms) +
                              " ms after " + std::to_string(previous_ms) + " ms");
      }
      const long long step = stamp_ms - previous_ms;
      if (step != 1) recording.timestamp_gaps.push_back(index);
      if (step <= kLongestSampleStep_ms) {
        ++steps;
        step_time_ms += step;
      }
    }
    previous_ms = stamp_ms;
    recording.acceleration_m_s2.push_back(accel_g * kStandardGravity_m_s2);
    recording.time_s.push_back(static_cast<double>(stamp_ms - first_ms) * 1e-3);
  }

  const std::size_t rows = recording.acceleration_m_s2.size();
  if (rows < 2) {
    throw FormatError(
        file, "", "expected at least 2 data rows after the header, found " + std::to_string(rows));
  }
  if (step_time_ms == 0) {
    throw FormatError(file, "column 'timestamp'",
                      "expected 1000 Hz, found timestamps that never advance by a sample step "
                      "(1-100 ms)");
  }
  const double measured_hz =
      static_cast<double>(steps) * 1000.0 / static_cast<double>(step_time_ms);
  if (std::abs(measured_hz - kPaperAccelerometerRate_hz) >
      kVibrationRateTolerance * kPaperAccelerometerRate_hz) {
    throw FormatError(file, "column 'timestamp'",
                      "expected 1000 Hz, found " + std::to_string(measured_hz) + " Hz (" +
                          std::to_string(steps) + " sample steps over " +
                          std::to_string(step_time_ms) + " ms)");
  }
  recording.sample_rate_hz = kPaperAccelerometerRate_hz;
  return recording;
}

}  // namespace nibrig::model::io
