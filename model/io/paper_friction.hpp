// Importer for the seed paper's friction recordings (../shared/data/piovarci2018/friction): the
// force sensor on the measurement arm while the turntable drags a tool over a surface, converted
// from raw sensor counts to newtons exactly as the authors' analysis does.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace nibrig::model::io {

// OptoForce sensitivity used by the upstream analysis (ProcessMeasurements.m): 403.2 counts per
// newton at the sensor. The arm amplifies the force at the tip by a lever factor that is part of
// each file name, so tip force = counts / kOptoForceCountsPerNewton / lever_factor.
inline constexpr double kOptoForceCountsPerNewton = 403.2;

// The sensor's sampling rate. The real files measure 999.0-1001.0 Hz (rows arrive in USB batches);
// a file more than 5 % off was not recorded by this set-up and is rejected.
inline constexpr double kOptoForceRate_hz = 1000.0;

// The ranges a recording's load and lever factor are held to, from its name or stated by a face
// (whose options check the same numbers). The paper's arm pressed with 2.2 N: a hundredth of a
// newton is a pen resting on paper, 50 N breaks a tip. Its lever factors are 13.3-14.1; one below
// 0.1 or above 100 is a typo that would scale every force by orders of magnitude.
inline constexpr double kLightestFrictionLoadN = 0.01, kHeaviestFrictionLoadN = 50.0;
inline constexpr double kSmallestLeverFactor = 0.1, kLargestLeverFactor = 100.0;
// A row's force at the tip beyond this is a damaged count, not a measurement: 20 times the
// heaviest load, far beyond any drag a tool survives.
inline constexpr double kLargestTipForceN = 1000.0;

// <tool>_<surface>_<load>N_<lever>_<rep>.csv[.gz], e.g. vero1_glass_2.2N_13.7_1.csv.gz.
struct FrictionFileName {
  std::string tool, surface;
  double normal_load_N = 0.0;
  double lever_factor = 0.0;
  int repetition = 0;
};

// Throws FormatError "unparsable file name, expected
// <tool>_<surface>_<load>N_<lever>_<rep>.csv[.gz]", and naming the load or lever factor outside the
// ranges above.
FrictionFileName parse_friction_file_name(const std::filesystem::path& file);

struct FrictionRecording {
  FrictionFileName name;
  std::filesystem::path source;
  double sample_rate_hz = 0.0;  // (rows - 1) / duration
  // Seconds since the first row. The sensor's rows arrive in batches sharing one wall-clock stamp,
  // so this is a staircase; use sample_rate_hz for a uniform time base.
  std::vector<double> time_s;
  std::vector<double> force_x_N, force_y_N;
  // The Z column, which the upstream analysis (ProcessMeasurements.m) takes as the drag force.
  std::vector<double> tangential_force_N;
  // What the reader had to work around (coarse timestamps, a cut-off last row, edited counts);
  // callers show these to the user.
  std::vector<std::string> warnings;
};

// Reads `TimeStamp,X,Y,Z` rows. TimeStamp is the wall clock "H:M:S.ms" with every part unpadded, so
// "23.76" means 23 s + 76 ms; a wrap past midnight is handled. Files re-saved by a spreadsheet
// carry "M:SS.t" stamps whose fraction is meaningless: their rate is counted over whole seconds and
// time_s is uniform (with a warning). Throws FormatError "expected about 1000 Hz ..." for another
// rate.
FrictionRecording read_paper_friction(const std::filesystem::path& file);
// The same with the name's parts given instead of parsed, for a file named anything (see
// paper_recording.hpp). Throws std::invalid_argument for an empty tool or surface, or a load or
// lever factor outside the ranges above ("load", "lever": what a face calls them); FormatError
// naming the line for a count whose tip force exceeds kLargestTipForceN.
FrictionRecording read_paper_friction(const std::filesystem::path& file, FrictionFileName name);

}  // namespace nibrig::model::io
