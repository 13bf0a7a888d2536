#include "model/forcing/leave_one_out_file.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "model/forcing/descriptor_error.hpp"
#include "model/io/atomic_file.hpp"
#include "model/io/format_error.hpp"
#include "model/io/quoted_csv.hpp"
#include "model/io/text_lines.hpp"

namespace nibrig::model::forcing {

namespace {

constexpr const char* kLooSpeedPrefix = "rms_db_";
constexpr const char* kLooSpeedSuffix = "_mm_s";

}  // namespace

std::string leave_one_out_csv_text(const LeaveOneOut& loo, const std::vector<double>& speeds_m_s) {
  std::string csv = "tool,surface,predictable,rms_db,baseline_rms_db";
  for (double v : speeds_m_s) csv += fmt::format(",{}{:g}{}", kLooSpeedPrefix, v * 1e3, kLooSpeedSuffix);
  csv += ",weighted_mean_error_percent,reason\n";
  for (const auto& r : loo.results) {
    csv += r.tool + ',' + r.surface + ',' + (r.predictable ? "yes" : "no") + ',';
    if (r.predictable)
      csv += fmt::format("{},{}", r.rms_db, r.baseline_rms_db);
    else
      csv += ',';
    for (std::size_t s = 0; s < speeds_m_s.size(); ++s)
      csv += ',' + (r.predictable ? fmt::format("{}", r.rms_db_by_speed[s]) : std::string());
    csv += ',' + (r.descriptor_error
                      ? fmt::format("{}", percent_off(r.descriptor_error->log10_weighted_mean))
                      : std::string());
    std::string reason = r.reason;
    std::replace(reason.begin(), reason.end(), '"', '\'');
    csv += ",\"" + reason + "\"\n";
  }
  return csv;
}

void write_leave_one_out_csv(const std::filesystem::path& file, const LeaveOneOut& loo,
                             const std::vector<double>& speeds_m_s) {
  io::write_file_atomically(file, leave_one_out_csv_text(loo, speeds_m_s));
}

LeaveOneOutTable read_leave_one_out_csv(const std::filesystem::path& file) {
  const io::QuotedCsv csv = io::read_quoted_csv(file);
  const auto& h = csv.header;
  const std::string prefix = kLooSpeedPrefix, suffix = kLooSpeedSuffix;
  bool shaped = h.size() >= 7 && h[0] == "tool" && h[1] == "surface" && h[2] == "predictable" &&
                h[3] == "rms_db" && h[4] == "baseline_rms_db" &&
                h[h.size() - 2] == "weighted_mean_error_percent" && h.back() == "reason";
  LeaveOneOutTable table;
  for (std::size_t c = 5; shaped && c + 2 < h.size(); ++c) {
    const std::string& name = h[c];
    shaped = name.size() > prefix.size() + suffix.size() && name.rfind(prefix, 0) == 0 &&
             name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
    if (shaped)
      table.speeds_mm_s.push_back(io::parse_number(
          std::string_view(name).substr(prefix.size(), name.size() - prefix.size() - suffix.size()),
          file, 1, name));
  }
  if (!shaped)
    throw io::FormatError(file, io::line_place(1),
                          "expected the header 'tool,surface,predictable,rms_db,baseline_rms_db,"
                          "rms_db_<speed>_mm_s...,weighted_mean_error_percent,reason'");
  const std::size_t speeds = table.speeds_mm_s.size();
  for (std::size_t r = 0; r < csv.rows.size(); ++r) {
    const auto& f = csv.rows[r];
    const std::size_t line = csv.line_numbers[r];
    LeaveOneOutRow row;
    row.tool = f[0];
    row.surface = f[1];
    if (f[2] != "yes" && f[2] != "no")
      throw io::FormatError(file, io::field_place(line, "predictable"),
                            "expected yes or no, found " + io::in_quotes(f[2]));
    row.predictable = f[2] == "yes";
    row.rms_db = io::parse_optional_number(f[3], file, line, h[3]);
    row.baseline_rms_db = io::parse_optional_number(f[4], file, line, h[4]);
    for (std::size_t s = 0; s < speeds; ++s)
      row.rms_db_by_speed.push_back(io::parse_optional_number(f[5 + s], file, line, h[5 + s]));
    row.weighted_mean_error_percent = io::parse_optional_number(f[5 + speeds], file, line, h[5 + speeds]);
    row.reason = f[6 + speeds];
    table.rows.push_back(std::move(row));
  }
  return table;
}

}  // namespace nibrig::model::forcing
