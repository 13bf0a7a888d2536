// The leave-one-out table (`nibrig forcing loo -o`, FORMATS.md "Leave-one-out errors"): per
// held-out exemplar whether it could be predicted, its RMS dB error overall, the model-free
// baseline's, per speed, and its weighted mean vibration's error in per cent.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "model/forcing/leave_one_out.hpp"

namespace nibrig::model::forcing {

// tool,surface,predictable,rms_db,baseline_rms_db,rms_db_<v>_mm_s per speed of `speeds_m_s`,
// weighted_mean_error_percent,reason: numbers with the digits that read back to the same double,
// empty where not predictable or not computed; the reason quoted, its own quotes made '.
std::string leave_one_out_csv_text(const LeaveOneOut& loo, const std::vector<double>& speeds_m_s);
// Written atomically; throws as io::write_file_atomically.
void write_leave_one_out_csv(const std::filesystem::path& file, const LeaveOneOut& loo,
                             const std::vector<double>& speeds_m_s);

struct LeaveOneOutRow {
  std::string tool, surface;
  bool predictable = false;
  std::optional<double> rms_db, baseline_rms_db;
  std::vector<std::optional<double>> rms_db_by_speed;  // one per LeaveOneOutTable::speeds_mm_s
  std::optional<double> weighted_mean_error_percent;
  std::string reason;
};
struct LeaveOneOutTable {
  std::vector<double> speeds_mm_s;  // from the header's rms_db_<v>_mm_s columns
  std::vector<LeaveOneOutRow> rows;
};
// Throws io::FormatError naming the file, line and field: a header of another shape, predictable
// other than yes or no, a number that is not one.
LeaveOneOutTable read_leave_one_out_csv(const std::filesystem::path& file);

}  // namespace nibrig::model::forcing
