#include "model/io/paper_friction.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "model/io/format_error.hpp"
#include "model/io/text_lines.hpp"

namespace nibrig::model::io {

namespace {

constexpr const char* kFrictionName = "<tool>_<surface>_<load>N_<lever>_<rep>.csv[.gz]";
constexpr const char* kFrictionHeader = "TimeStamp,X,Y,Z";
constexpr double kSecondsPerDay = 86400.0;
constexpr long long kSecondsPerHour = 3600;
constexpr double kFrictionRateTolerance = 0.05;

[[noreturn]] void bad_friction_name(const std::filesystem::path& file, const std::string& why) {
  throw FormatError(
      file, "", "unparsable file name, expected " + std::string(kFrictionName) + " (" + why + ")");
}

// Digits only, no sign: the parts of a wall-clock stamp.
std::optional<long long> digits(std::string_view text, std::size_t max_digits) {
  if (text.empty() || text.size() > max_digits) return std::nullopt;
  long long value = 0;
  for (char c : text) {
    if (c < '0' || c > '9') return std::nullopt;
    value = value * 10 + (c - '0');
  }
  return value;
}

struct Stamp {
  bool coarse = false;
  double seconds = 0.0;   // full stamps: seconds since midnight, millisecond resolution
  long long whole_s = 0;  // coarse stamps: minutes * 60 + whole seconds (the hour is lost)
};

std::optional<Stamp> parse_stamp(std::string_view text) {
  std::vector<std::string_view> parts = split_fields(text, ':');
  if (parts.size() == 3) {
    const std::size_t dot = parts[2].find('.');
    const auto hours = digits(parts[0], 2);
    const auto minutes = digits(parts[1], 2);
    const auto secs = digits(parts[2].substr(0, dot), 2);
    // Milliseconds are written as an unpadded integer: "23.76" is 23 s + 76 ms, not 23.76 s.
    const auto millis = dot == std::string_view::npos ? std::optional<long long>(0)
                                                      : digits(parts[2].substr(dot + 1), 3);
    if (!hours || !minutes || !secs || !millis || *hours > 23 || *minutes > 59 || *secs > 60) {
      return std::nullopt;
    }
    return Stamp{false,
                 static_cast<double>(*hours * 3600 + *minutes * 60 + *secs) +
                     static_cast<double>(*millis) / 1000.0,
                 0};
  }
  if (parts.size() == 2) {
    // "M:SS.t": a spreadsheet re-saved the file and reformatted the stamp, dropping the hour and
    // rounding the (unpadded, hence misread) milliseconds to tenths. Only whole seconds survive.
    const std::size_t dot = parts[1].find('.');
    const auto minutes = digits(parts[0], 2);
    const auto secs = digits(parts[1].substr(0, dot), 2);
    const auto tenths = dot == std::string_view::npos ? std::optional<long long>(0)
                                                      : digits(parts[1].substr(dot + 1), 6);
    if (!minutes || !secs || !tenths || *minutes > 59 || *secs > 60) return std::nullopt;
    return Stamp{true, 0.0, *minutes * 60 + *secs};
  }
  return std::nullopt;
}

bool is_whole(double value) { return std::floor(value) == value; }

void check_rate(double rate_hz, const std::filesystem::path& file, const std::string& evidence) {
  if (std::abs(rate_hz - kOptoForceRate_hz) > kFrictionRateTolerance * kOptoForceRate_hz) {
    throw FormatError(file, "column 'TimeStamp'",
                      "expected about 1000 Hz (the force sensor's rate), found " +
                          std::to_string(rate_hz) + " Hz (" + evidence + ")");
  }
}

// Numbers in messages as a person types them ("1e+308", "0.01").
std::string friction_number(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

std::string friction_range(double low, double high) { return friction_number(low) + " to " + friction_number(high); }

}  // namespace

FrictionFileName parse_friction_file_name(const std::filesystem::path& file) {
  const auto stem = csv_stem(file);
  if (!stem) bad_friction_name(file, "not a .csv or .csv.gz file");
  std::vector<std::string_view> tokens = split_fields(*stem, '_');
  if (tokens.size() < 5) bad_friction_name(file, "expected at least 5 parts separated by '_'");
  // Read from the right so that a tool id may itself contain '_'.
  const std::size_t n = tokens.size();
  const std::string_view load_token = tokens[n - 3];
  const std::string_view lever_token = tokens[n - 2];
  const std::string_view rep_token = tokens[n - 1];
  FrictionFileName name;
  name.surface = std::string(tokens[n - 4]);
  for (std::size_t i = 0; i + 4 < n; ++i) {
    if (i > 0) name.tool += '_';
    name.tool += tokens[i];
  }
  if (name.tool.empty() || name.surface.empty()) bad_friction_name(file, "empty tool or surface");
  for (std::string_view part : tokens) {
    if (part.empty()) bad_friction_name(file, "empty part between '_'");
  }
  if (load_token.back() != 'N')
    bad_friction_name(file, "the load must end in 'N', found " + in_quotes(load_token));
  const auto load = positive_number_in_name(load_token.substr(0, load_token.size() - 1));
  if (!load) bad_friction_name(file, "the load must be a positive number, found " + in_quotes(load_token));
  const auto lever = positive_number_in_name(lever_token);
  if (!lever)
    bad_friction_name(file, "the lever factor must be a positive number, found " + in_quotes(lever_token));
  const auto rep = digits(rep_token, 6);
  if (!rep || *rep < 1)
    bad_friction_name(file, "the repetition must be a whole number >= 1, found " + in_quotes(rep_token));
  if (!(*load >= kLightestFrictionLoadN && *load <= kHeaviestFrictionLoadN))
    throw FormatError(file, "file name",
                      "the load " + in_quotes(load_token) + " is outside " + friction_range(kLightestFrictionLoadN, kHeaviestFrictionLoadN) +
                          " N (a pen resting on paper to a tip's breaking load)");
  if (!(*lever >= kSmallestLeverFactor && *lever <= kLargestLeverFactor))
    throw FormatError(file, "file name",
                      "the lever factor " + in_quotes(lever_token) + " is outside " +
                          friction_range(kSmallestLeverFactor, kLargestLeverFactor) + " (the paper's are 13.3-14.1)");
  name.normal_load_N = *load;
  name.lever_factor = *lever;
  name.repetition = static_cast<int>(*rep);
  return name;
}

FrictionRecording read_paper_friction(const std::filesystem::path& file) {
  return read_paper_friction(file, parse_friction_file_name(file));
}

FrictionRecording read_paper_friction(const std::filesystem::path& file, FrictionFileName name) {
  if (name.tool.empty() || name.surface.empty())
    throw std::invalid_argument(file.string() + ": a recording needs a tool and a surface id");
  // Both divide the counts: one outside its range would make every force meaningless (a lever of
  // 1e308 gives μ 1e-308).
  if (!(name.normal_load_N >= kLightestFrictionLoadN && name.normal_load_N <= kHeaviestFrictionLoadN))
    throw std::invalid_argument(file.string() + ": load " + friction_number(name.normal_load_N) +
                                " N: expected a normal load in N, " +
                                friction_range(kLightestFrictionLoadN, kHeaviestFrictionLoadN));
  if (!(name.lever_factor >= kSmallestLeverFactor && name.lever_factor <= kLargestLeverFactor))
    throw std::invalid_argument(file.string() + ": lever " + friction_number(name.lever_factor) +
                                ": expected a lever factor, " +
                                friction_range(kSmallestLeverFactor, kLargestLeverFactor) + " (the paper's: 13.3-14.1)");
  FrictionRecording recording;
  recording.name = std::move(name);
  recording.source = file;

  CsvReader csv(file, kFrictionHeader);
  const std::size_t c_time = csv.header().column("TimeStamp");
  const std::size_t c_x = csv.header().column("X");
  const std::size_t c_y = csv.header().column("Y");
  const std::size_t c_z = csv.header().column("Z");
  const std::size_t needed = std::max({c_time, c_x, c_y, c_z}) + 1;
  const double newtons_per_count = 1.0 / kOptoForceCountsPerNewton / recording.name.lever_factor;

  std::vector<double> stamps_s;    // full stamps, unwrapped past midnight
  std::vector<long long> whole_s;  // coarse stamps, unwrapped past the hour
  std::optional<bool> coarse;
  double day_offset = 0.0;
  long long hour_offset = 0;
  long long latest_whole = 0;
  std::size_t edited_counts = 0;
  std::size_t first_edited_line = 0;

  std::vector<std::string_view> fields;
  while (csv.next(fields)) {
    const std::size_t line = csv.line_number();
    if (csv.cut_off_last_row(fields, needed, recording.warnings)) break;
    csv.require_fields(fields, needed);
    const auto stamp = parse_stamp(fields[c_time]);
    if (!stamp) {
      throw FormatError(file, field_place(line, "TimeStamp"),
                        "expected a wall-clock time H:M:S.ms like 13:2:48.219, found " +
                            in_quotes(fields[c_time]));
    }
    if (!coarse) coarse = stamp->coarse;
    if (*coarse != stamp->coarse) {
      throw FormatError(file, field_place(line, "TimeStamp"),
                        std::string("expected the same time format as the first row (") +
                            (*coarse ? "M:SS.t" : "H:M:S.ms") + "), found " +
                            in_quotes(fields[c_time]));
    }
    if (!*coarse) {
      double t = stamp->seconds + day_offset;
      if (!stamps_s.empty() && t < stamps_s.back() - kSecondsPerDay / 2) {
        day_offset += kSecondsPerDay;  // the recording ran past midnight
        t += kSecondsPerDay;
      }
      if (!stamps_s.empty() && t < stamps_s.back()) {
        throw FormatError(file, field_place(line, "TimeStamp"),
                          "expected time to increase, found " + in_quotes(fields[c_time]) +
                              " after " + std::to_string(stamps_s.back() - day_offset) +
                              " s since midnight");
      }
      stamps_s.push_back(t);
    } else {
      long long t = stamp->whole_s + hour_offset;
      if (!whole_s.empty() && t < latest_whole - kSecondsPerHour / 2) {
        hour_offset += kSecondsPerHour;  // minutes wrapped past the (dropped) hour
        t += kSecondsPerHour;
      }
      // Rounding to tenths can push a stamp to the next second and back, never further.
      if (!whole_s.empty() && t < latest_whole - 1) {
        throw FormatError(file, field_place(line, "TimeStamp"),
                          "expected time to increase (up to 1 s of rounding), found " +
                              in_quotes(fields[c_time]));
      }
      latest_whole = whole_s.empty() ? t : std::max(latest_whole, t);
      whole_s.push_back(t);
    }
    const double x = parse_number(fields[c_x], file, line, "X");
    const double y = parse_number(fields[c_y], file, line, "Y");
    const double z = parse_number(fields[c_z], file, line, "Z");
    for (const auto& [count, column] : {std::pair{x, "X"}, std::pair{y, "Y"}, std::pair{z, "Z"}})
      if (std::abs(count * newtons_per_count) > kLargestTipForceN)
        throw FormatError(file, field_place(line, column),
                          "expected a force at the tip of at most " + friction_number(kLargestTipForceN) +
                              " N, found " + friction_number(count) + " counts (" +
                              friction_number(count * newtons_per_count) + " N)");
    if (!is_whole(x) || !is_whole(y) || !is_whole(z)) {
      if (edited_counts++ == 0) first_edited_line = line;
    }
    recording.force_x_N.push_back(x * newtons_per_count);
    recording.force_y_N.push_back(y * newtons_per_count);
    recording.tangential_force_N.push_back(z * newtons_per_count);
  }

  const std::size_t rows = recording.tangential_force_N.size();
  if (rows < 2) {
    throw FormatError(file, "",
                      "expected at least 2 data rows after the header " +
                          std::string(kFrictionHeader) + ", found " + std::to_string(rows));
  }
  if (edited_counts > 0) {
    recording.warnings.push_back(
        std::to_string(edited_counts) + " rows hold non-integer sensor counts (first at line " +
        std::to_string(first_edited_line) + "): the file was edited after recording");
  }

  if (!*coarse) {
    const double duration = stamps_s.back() - stamps_s.front();
    if (duration <= 0.0) {
      throw FormatError(
          file, "",
          "all " + std::to_string(rows) + " rows share one timestamp: cannot tell the sample rate");
    }
    recording.sample_rate_hz = static_cast<double>(rows - 1) / duration;
    check_rate(recording.sample_rate_hz, file,
               std::to_string(rows - 1) + " steps over " + std::to_string(duration) + " s");
    recording.time_s.reserve(rows);
    for (double t : stamps_s) recording.time_s.push_back(t - stamps_s.front());
    return recording;
  }

  // Coarse stamps: rows are counted over the whole seconds strictly inside the recording. Rounding
  // moves a few rows across a second boundary but keeps the inner total to within a batch.
  const long long first = whole_s.front();
  const long long last = whole_s.back();
  if (last - first < 2) {
    throw FormatError(file, "",
                      "timestamps in M:SS.t form span less than 2 whole seconds: cannot "
                      "count the sample rate");
  }
  std::size_t inner_rows = 0;
  for (long long t : whole_s) inner_rows += (t > first && t < last) ? 1 : 0;
  const auto inner_seconds = static_cast<double>(last - first - 1);
  recording.sample_rate_hz = static_cast<double>(inner_rows) / inner_seconds;
  check_rate(recording.sample_rate_hz, file,
             std::to_string(inner_rows) + " rows in " + std::to_string(last - first - 1) +
                 " whole seconds");
  recording.time_s.reserve(rows);
  for (std::size_t i = 0; i < rows; ++i) {
    recording.time_s.push_back(static_cast<double>(i) / recording.sample_rate_hz);
  }
  recording.warnings.push_back(
      "timestamps were reformatted by a spreadsheet (M:SS.t, hour dropped, milliseconds misread): "
      "time_s is uniform at " +
      std::to_string(recording.sample_rate_hz) + " Hz, counted over " +
      std::to_string(last - first - 1) + " whole seconds");
  return recording;
}

}  // namespace nibrig::model::io
