// The hold-out table (`nibrig forcing holdout -o`, FORMATS.md "Hold-out errors"): per held-out
// tool and speed the RMS dB error of the interpolated prediction beside the two no-interpolation
// baselines, and per tool over all speeds (speed "all") also the measured neighbours'.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "model/design/interpolation_check.hpp"

namespace nibrig::model::design {

// The names of the columns that depend on what was held out: the two baselines' and the two
// measured neighbours'.
struct HoldOutColumns {
  std::array<std::string, 2> baseline, measured;
};
// A tip held out: "tip_1mm_curve_rms_db", ...; "measured_lower_tip_rms_db", ...
HoldOutColumns tip_hold_out_columns(double lower_tip_m, double upper_tip_m);
// A material held out as a mix: "vero_curve_rms_db", ...; "measured_vero_rms_db", ...
HoldOutColumns material_hold_out_columns(const std::string& first, const std::string& second);

// tool,surface,speed_mm_s,interpolated_rms_db,<baselines>,<measured>,not_predictable: a row per
// speed of `speeds_m_s`, then the tool's row over all speeds; a tool that could not be predicted
// has that row alone, with its reason (quoted). Numbers with the digits that read back to the same
// double; a measured neighbour that was not measured is an empty field.
std::string hold_out_csv_text(std::span<const InterpolatedPrediction> predictions,
                              const std::vector<double>& speeds_m_s, const HoldOutColumns& columns);
// Written atomically; throws as io::write_file_atomically.
void write_hold_out_csv(const std::filesystem::path& file,
                        std::span<const InterpolatedPrediction> predictions,
                        const std::vector<double>& speeds_m_s, const HoldOutColumns& columns);

struct HoldOutRow {
  std::string tool, surface;
  std::optional<double> speed_mm_s;  // none: the row over all speeds
  // Each none where the field is empty (a tool not predicted; the measured neighbours per speed).
  std::optional<double> interpolated_rms_db;
  std::array<std::optional<double>, 2> baseline_rms_db, measured_rms_db;
  std::string not_predictable;
};
struct HoldOutTable {
  HoldOutColumns columns;
  std::vector<HoldOutRow> rows;
};
// Throws io::FormatError naming the file, line and field: a header of another shape, a number
// that is not one.
HoldOutTable read_hold_out_csv(const std::filesystem::path& file);

}  // namespace nibrig::model::design
