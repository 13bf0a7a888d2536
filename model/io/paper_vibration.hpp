// Importer for the seed paper's accelerometer recordings (../shared/data/piovarci2018/vibration):
// the tool enclosure's acceleration at 1000 Hz while the turntable drags it over a surface, in
// m/s², with tool ids that match the friction files' ids for the same physical tool.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace nibrig::model::io {

inline constexpr double kStandardGravity_m_s2 = 9.80665;  // the recordings are in g
inline constexpr double kPaperAccelerometerRate_hz = 1000.0;
// A sample beyond this many g is a damaged value, not a measurement: 1000 g is far beyond any
// stylus (the catalog's amplitudes are held to the same).
inline constexpr double kLargestPaperAcceleration_g = 1000.0;

// Decoded from arm_<...>.csv[.gz]. The forms and their canonical tool ids:
//   arm_<tool>_<surface>                        real or commercial tool: "p2h", "apencil"
//   arm_<material>_<tip>_<surface>              printed tool: "vero1", "DM852"
//   arm_teflon_<tip>_<surface>                  teflon-taped tool: "teflon4"
//   arm_plain_<material>_<tip>_<surface>        plain printed tip: "DM851" (variant "plain")
//   arm_plain_<material>_<tip>_nailN_<surface>  nail variants: "DM851_nail1" (variant "nail1")
//   arm_penh_<material>_<surface>               pen-holder design: "penh_DM85" (variant "penh")
// Printed ids are material + tip diameter in mm, as in the friction file names.
struct VibrationFileName {
  std::string tool;
  std::string material;  // vero, DM85, DM95, teflon; empty for real and commercial tools
  std::optional<double> tip_diameter_m;
  std::string variant;  // plain, penh, nail1, nail2 or empty
  std::string surface;
};

// Throws FormatError "unparsable file name, expected arm_<tool>_<surface>.csv[.gz] or ...".
VibrationFileName parse_vibration_file_name(const std::filesystem::path& file);

// True for arm_*.csv[.gz]. vibration/prints/ts.csv.gz is a bare list of timestamps, not a
// recording.
bool is_paper_vibration_file(const std::filesystem::path& file);

struct VibrationRecording {
  VibrationFileName name;
  std::filesystem::path source;
  double sample_rate_hz = 0.0;            // nominal 1000 Hz, checked against the timestamps
  std::vector<double> acceleration_m_s2;  // the xAccel column, as upstream uses it
  std::vector<double> time_s;  // from the millisecond timestamps, relative to the first row
  // Indices i where timestamp[i] - timestamp[i-1] != 1 ms: dropped samples (2-20 ms) and pauses
  // between sweeps (seconds). A spectrum window should not straddle one.
  std::vector<std::size_t> timestamp_gaps;
  std::vector<std::string> warnings;  // a cut-off last row that was dropped
};

// Header `time,timestamp,xAccel,yAccel,zAccel,xxx`, or a blank header `,,,,,` with the same column
// positions. Throws FormatError "expected 1000 Hz, found ..." when the timestamps show another
// rate, and naming the line for an acceleration beyond kLargestPaperAcceleration_g.
VibrationRecording read_paper_vibration(const std::filesystem::path& file);
// The same with the name's parts given instead of parsed, for a file named anything (see
// paper_recording.hpp). Throws std::invalid_argument for an empty tool or surface.
VibrationRecording read_paper_vibration(const std::filesystem::path& file, VibrationFileName name);

}  // namespace nibrig::model::io
