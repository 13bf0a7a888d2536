// The report a live comparison leaves behind (`nibrig rig compare --report DIR` writes it as
// DIR/comparison.json): per speed bin how far the simulation's spectrum was from the measured one,
// so that a run can be compared with the catalog's repeatability and with other runs.
//
// {"format": "nibrig-comparison", "version": 1, "tool", "surface",
//  "spectrogram": {"sample_rate_hz", "segment_length", "hop", "window"},
//  "band_hz": [min, max]  (half-open: the catalog's band),
//  "distance": the definition of lsd_db in words,
//  "speed_bins": [{"min_speed_mm_s", "max_speed_mm_s", "mean_speed_mm_s", "rows", "lsd_db",
//                  "measured_weighted_mean", "simulated_weighted_mean",
//                  "weighted_mean_log10_difference"}],
//  "overall": {"bins_with_rows", "rows", "rows_outside_speed_range", "mean_lsd_db",
//              "mean_weighted_mean_log10_difference"},
//  "capture": {"rows_analysed", "rows_without_speed", "blocks_dropped"}}
// Speeds in mm/s (the file boundary's unit, as in every nibrig file). A value that does not exist
// (an empty bin's distance, a mean over no bin) is null, never 0.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "rig/live_comparison.hpp"

namespace nibrig::rig {

nlohmann::json comparison_json(const std::string& tool, const std::string& surface,
                               const ComparisonTable& table,
                               const LiveComparisonSettings& settings);

// Written whole or not at all (model::io::write_file_atomically); std::runtime_error naming the
// file when it cannot be.
void write_comparison_json(const std::filesystem::path& file, const std::string& tool,
                           const std::string& surface, const ComparisonTable& table,
                           const LiveComparisonSettings& settings);

}  // namespace nibrig::rig
