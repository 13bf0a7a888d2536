#include "model/io/paper_drawing.hpp"

#include <algorithm>
#include <cmath>

#include "model/io/format_error.hpp"
#include "model/io/text_lines.hpp"

namespace nibrig::model::io {

namespace {

constexpr const char* kDrawingHeader =
    "Unix Timestamp,X,Y,Z,Phi,Theta,F,Ground,Touch,Speed,Acceeration";
constexpr long long kLongestFrameStep_ms = 50;
// A tracking rate, not a unit error: the paper's tracker ran at 111-139 Hz and pen tablets report at
// 100-300 Hz (the XP-Pen Deco 01 V2 at 266 Hz), which a stroke recorded from one keeps. 30 Hz leaves
// room below for what a recording loses (libinput sends nothing while the pen holds still, and
// such pauses up to 50 ms count as frame steps); 500 Hz is the fastest whose steps, 2 ms, the
// format's whole-millisecond stamps still tell apart.
constexpr double kLowestFrameRate_hz = 30.0;
constexpr double kHighestFrameRate_hz = 500.0;
// The force a stroke may press with, as `render --force` takes it (50 N); the artists' recordings
// read -1.7 to 9.4 N, the sensor's offset making some slightly negative.
constexpr double kHeaviestForce_N = 50.0;

}  // namespace

DrawingTrajectory read_paper_drawing(const std::filesystem::path& file) {
  DrawingTrajectory trajectory;
  trajectory.source = file;
  const auto stem = csv_stem(file);
  const std::vector<std::string_view> tokens =
      stem ? split_fields(*stem, '_') : std::vector<std::string_view>{};
  if (tokens.size() < 3 ||
      std::any_of(tokens.begin(), tokens.end(), [](std::string_view t) { return t.empty(); })) {
    throw FormatError(file, "",
                      "unparsable file name, expected <tool>_<surface>_<subject>.csv[.gz]");
  }
  trajectory.tool = std::string(tokens[0]);
  trajectory.surface = std::string(tokens[1]);
  trajectory.subject = stem->substr(tokens[0].size() + tokens[1].size() + 2);

  CsvReader csv(file, kDrawingHeader);
  const std::size_t c_time = csv.header().column("Unix Timestamp");
  const std::size_t c_x = csv.header().column("X");
  const std::size_t c_y = csv.header().column("Y");
  const std::size_t c_force = csv.header().column("F");
  const std::size_t c_touch = csv.header().column("Touch");
  const std::size_t c_speed = csv.header().column("Speed");
  const std::size_t needed = std::max({c_time, c_x, c_y, c_force, c_touch, c_speed}) + 1;

  std::vector<double> speed_mm_per_frame;
  std::vector<std::string_view> fields;
  long long first_ms = 0;
  long long previous_ms = 0;
  long long frames = 0;
  long long frame_time_ms = 0;
  while (csv.next(fields)) {
    const std::size_t line = csv.line_number();
    if (csv.cut_off_last_row(fields, needed, trajectory.warnings)) break;
    csv.require_fields(fields, needed);
    const long long stamp_ms = parse_unix_ms(fields[c_time], file, line, "Unix Timestamp");
    if (trajectory.time_s.empty()) {
      first_ms = stamp_ms;
    } else {
      if (stamp_ms <= previous_ms) {
        throw FormatError(file, field_place(line, "Unix Timestamp"),
                          "expected time to increase, found " + std::to_string(stamp_ms) +
                              " ms after " + std::to_string(previous_ms) + " ms");
      }
      if (stamp_ms - previous_ms <= kLongestFrameStep_ms) {
        ++frames;
        frame_time_ms += stamp_ms - previous_ms;
      }
    }
    previous_ms = stamp_ms;
    const double x_mm = parse_number(fields[c_x], file, line, "X");
    const double y_mm = parse_number(fields[c_y], file, line, "Y");
    const double force = parse_number(fields[c_force], file, line, "F");
    if (std::abs(force) > kHeaviestForce_N) {
      throw FormatError(file, field_place(line, "F"),
                        "expected a force within +-" + std::to_string(static_cast<int>(kHeaviestForce_N)) +
                            " N (a pen's, as render --force takes), found " + in_quotes(fields[c_force]));
    }
    const long long touch = parse_integer(fields[c_touch], file, line, "Touch");
    if (touch != 0 && touch != 1) {
      throw FormatError(file, field_place(line, "Touch"),
                        "expected 0 or 1, found " + in_quotes(fields[c_touch]));
    }
    const double speed = parse_number(fields[c_speed], file, line, "Speed");
    if (speed < 0.0) {
      throw FormatError(
          file, field_place(line, "Speed"),
          "expected a distance per frame (>= 0), found " + in_quotes(fields[c_speed]));
    }
    trajectory.time_s.push_back(static_cast<double>(stamp_ms - first_ms) * 1e-3);
    trajectory.x_m.push_back(x_mm * 1e-3);
    trajectory.y_m.push_back(y_mm * 1e-3);
    trajectory.normal_force_N.push_back(force);
    trajectory.touching.push_back(touch == 1);
    speed_mm_per_frame.push_back(speed);
  }

  if (trajectory.time_s.size() < 2) {
    throw FormatError(file, "",
                      "expected at least 2 data rows after the header, found " +
                          std::to_string(trajectory.time_s.size()));
  }
  if (frames == 0) {
    throw FormatError(
        file, "column 'Unix Timestamp'",
        "expected frames at most 50 ms apart, found none: cannot tell the frame rate");
  }
  trajectory.frame_rate_hz =
      static_cast<double>(frames) * 1000.0 / static_cast<double>(frame_time_ms);
  if (trajectory.frame_rate_hz < kLowestFrameRate_hz ||
      trajectory.frame_rate_hz > kHighestFrameRate_hz) {
    throw FormatError(
        file, "column 'Unix Timestamp'",
        "expected about 120 Hz (the paper's tracker) or a pen tablet's 100-300 Hz (" +
            std::to_string(static_cast<int>(kLowestFrameRate_hz)) + "-" +
            std::to_string(static_cast<int>(kHighestFrameRate_hz)) + " Hz accepted), found " +
            std::to_string(trajectory.frame_rate_hz) + " Hz (" + std::to_string(frames) +
            " frame steps over " + std::to_string(frame_time_ms) + " ms)");
  }
  trajectory.speed_m_s.reserve(speed_mm_per_frame.size());
  for (double speed : speed_mm_per_frame) {
    trajectory.speed_m_s.push_back(speed * trajectory.frame_rate_hz * 1e-3);
  }
  return trajectory;
}

}  // namespace nibrig::model::io
