// comparison.json: what a live comparison of a real tool with its simulation found
// (`nibrig rig compare --report DIR`), per speed bin how far the simulated spectrum was from the
// measured one, so that a run can be set beside the catalog's repeatability and beside other runs.
// FORMATS.md, "Live comparison", describes the file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace nibrig::model::io {

// A value that does not exist (an empty bin's distance, a mean over no bin) is NaN here and null
// in the file, never 0.
struct ComparisonBin {
  double min_speed_m_s = 0.0, max_speed_m_s = 0.0;
  double mean_speed_m_s = 0.0;
  std::uint64_t rows = 0;
  double lsd_db = 0.0;  // RMS over the band of 20·log10(simulated / measured) of the mean spectra
  double measured_weighted_mean = 0.0, simulated_weighted_mean = 0.0;
  double weighted_mean_log10_difference = 0.0;  // log10(simulated / measured)
};

// How the actuator followed the turntable while it played the simulation (`--play`).
struct ComparisonActuator {
  std::uint64_t contacts = 0;                      // contact frames its blocks applied
  double follow_mean_s = 0.0, follow_max_s = 0.0;  // from a frame's arrival to the engine
  double period_s = 0.0;                           // the actuator stream's period, for scale
};

struct ComparisonFile {
  std::string tool, surface;
  // The spectrograms the comparison was made of.
  double sample_rate_hz = 0.0;
  std::uint64_t segment_length = 0, hop = 0;
  std::string window;  // "hann" or "rectangular"
  // The frequencies the distances use: band_min_hz <= f < band_max_hz.
  double band_min_hz = 0.0, band_max_hz = 0.0;
  std::vector<ComparisonBin> bins;
  // Over the bins with rows, each counted once.
  std::uint64_t bins_with_rows = 0, rows = 0, rows_outside_speed_range = 0;
  double mean_lsd_db = 0.0, mean_weighted_mean_log10_difference = 0.0;
  // What the capture lost: rows without any speed sample, blocks the analysis never saw.
  std::uint64_t rows_analysed = 0, rows_without_speed = 0, blocks_dropped = 0;
  std::optional<ComparisonActuator> actuator;  // none when nothing played the simulation
};

// Whole or not at all (write_file_atomically); std::runtime_error naming the file when it cannot.
void write_comparison_file(const ComparisonFile& comparison, const std::filesystem::path& file);

// Throws FormatError naming the file and the field for another format or a newer version, a
// missing or mistyped field, speeds that are not 0 < min < max, a band that is not 0 <= min < max,
// or a bin whose rows are not a whole number.
ComparisonFile read_comparison_file(const std::filesystem::path& file);

}  // namespace nibrig::model::io
