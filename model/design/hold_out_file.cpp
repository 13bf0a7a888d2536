#include "model/design/hold_out_file.hpp"

#include <fmt/format.h>

#include "model/io/atomic_file.hpp"
#include "model/io/format_error.hpp"
#include "model/io/quoted_csv.hpp"
#include "model/io/text_lines.hpp"

namespace nibrig::model::design {

namespace {

constexpr std::size_t kHoldOutColumnCount = 9;

}  // namespace

HoldOutColumns tip_hold_out_columns(double lower_tip_m, double upper_tip_m) {
  return {{fmt::format("tip_{:g}mm_curve_rms_db", lower_tip_m * 1e3),
           fmt::format("tip_{:g}mm_curve_rms_db", upper_tip_m * 1e3)},
          {"measured_lower_tip_rms_db", "measured_upper_tip_rms_db"}};
}

HoldOutColumns material_hold_out_columns(const std::string& first, const std::string& second) {
  return {{first + "_curve_rms_db", second + "_curve_rms_db"},
          {"measured_" + first + "_rms_db", "measured_" + second + "_rms_db"}};
}

std::string hold_out_csv_text(std::span<const InterpolatedPrediction> predictions,
                              const std::vector<double>& speeds_m_s,
                              const HoldOutColumns& columns) {
  std::string csv = "tool,surface,speed_mm_s,interpolated_rms_db," + columns.baseline[0] + ',' +
                    columns.baseline[1] + ',' + columns.measured[0] + ',' + columns.measured[1] +
                    ",not_predictable\n";
  const auto measured = [](double rms) { return rms < 0 ? std::string() : fmt::format("{}", rms); };
  for (const auto& r : predictions) {
    const auto& c = r.comparison;
    if (!r.not_predictable.empty()) {
      csv += fmt::format("{},{},all,,,,,,{}\n", r.tool, r.surface, io::csv_quoted(r.not_predictable));
      continue;
    }
    for (std::size_t s = 0; s < speeds_m_s.size(); ++s)
      csv += fmt::format("{},{},{:g},{},{},{},,,\n", r.tool, r.surface, speeds_m_s[s] * 1e3,
                         c.interpolated.rms_db_by_speed[s], c.baselines[0].error.rms_db_by_speed[s],
                         c.baselines[1].error.rms_db_by_speed[s]);
    csv += fmt::format("{},{},all,{},{},{},{},{},\n", r.tool, r.surface, c.interpolated.rms_db,
                       c.baselines[0].error.rms_db, c.baselines[1].error.rms_db,
                       measured(r.measured_neighbour_rms_db[0]),
                       measured(r.measured_neighbour_rms_db[1]));
  }
  return csv;
}

void write_hold_out_csv(const std::filesystem::path& file,
                        std::span<const InterpolatedPrediction> predictions,
                        const std::vector<double>& speeds_m_s, const HoldOutColumns& columns) {
  io::write_file_atomically(file, hold_out_csv_text(predictions, speeds_m_s, columns));
}

HoldOutTable read_hold_out_csv(const std::filesystem::path& file) {
  const io::QuotedCsv csv = io::read_quoted_csv(file);
  const auto& h = csv.header;
  const bool shaped = h.size() == kHoldOutColumnCount && h[0] == "tool" && h[1] == "surface" &&
                      h[2] == "speed_mm_s" && h[3] == "interpolated_rms_db" &&
                      h[8] == "not_predictable";
  if (!shaped)
    throw io::FormatError(file, io::line_place(1),
                          "expected the header 'tool,surface,speed_mm_s,interpolated_rms_db,"
                          "<two baselines>,<two measured neighbours>,not_predictable'");
  HoldOutTable table;
  table.columns = {{h[4], h[5]}, {h[6], h[7]}};
  for (std::size_t r = 0; r < csv.rows.size(); ++r) {
    const auto& f = csv.rows[r];
    const std::size_t line = csv.line_numbers[r];
    HoldOutRow row;
    row.tool = f[0];
    row.surface = f[1];
    if (f[2] != "all") row.speed_mm_s = io::parse_number(f[2], file, line, h[2]);
    row.interpolated_rms_db = io::parse_optional_number(f[3], file, line, h[3]);
    for (std::size_t k = 0; k < 2; ++k) {
      row.baseline_rms_db[k] = io::parse_optional_number(f[4 + k], file, line, h[4 + k]);
      row.measured_rms_db[k] = io::parse_optional_number(f[6 + k], file, line, h[6 + k]);
    }
    row.not_predictable = f[8];
    table.rows.push_back(std::move(row));
  }
  return table;
}

}  // namespace nibrig::model::design
