#include "rig/comparison_report.hpp"

#include <cmath>

#include "model/io/atomic_file.hpp"

namespace nibrig::rig {

namespace {

// JSON has no NaN: a value that does not exist is null.
nlohmann::json number_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nullptr; }

constexpr double kMmPerM = 1000.0;

}  // namespace

nlohmann::json comparison_json(const std::string& tool, const std::string& surface,
                               const ComparisonTable& table,
                               const LiveComparisonSettings& settings) {
  nlohmann::json j;
  j["format"] = "nibrig-comparison";
  j["version"] = 1;
  j["tool"] = tool;
  j["surface"] = surface;
  const auto& sg = settings.spectrogram;
  j["spectrogram"] = {
      {"sample_rate_hz", settings.acceleration_rate_hz},
      {"segment_length", sg.segment_length},
      {"hop", sg.hop},
      {"window", sg.window == model::measure::Window::hann ? "hann" : "rectangular"}};
  j["band_hz"] = {settings.comparison.min_frequency_hz, settings.comparison.max_frequency_hz};
  j["distance"] =
      "lsd_db: RMS over the band's bins of 20 log10(simulated / measured) of the bin's mean "
      "amplitude spectra, dB; weighted_mean_log10_difference: log10(simulated / measured) of the "
      "threshold-weighted mean vibration";
  nlohmann::json bins = nlohmann::json::array();
  for (const auto& b : table.bins) {
    bins.push_back(
        {{"min_speed_mm_s", b.min_speed_m_s * kMmPerM},
         {"max_speed_mm_s", b.max_speed_m_s * kMmPerM},
         {"mean_speed_mm_s", number_or_null(b.mean_speed_m_s * kMmPerM)},
         {"rows", b.rows},
         {"lsd_db", number_or_null(b.lsd_db)},
         {"measured_weighted_mean", number_or_null(b.measured_weighted_mean)},
         {"simulated_weighted_mean", number_or_null(b.simulated_weighted_mean)},
         {"weighted_mean_log10_difference", number_or_null(b.weighted_mean_log10_difference)}});
  }
  j["speed_bins"] = std::move(bins);
  const auto& s = table.summary;
  j["overall"] = {{"bins_with_rows", s.bins_with_rows},
                  {"rows", s.rows},
                  {"rows_outside_speed_range", s.rows_outside_speed_range},
                  {"mean_lsd_db", number_or_null(s.mean_lsd_db)},
                  {"mean_weighted_mean_log10_difference",
                   number_or_null(s.mean_weighted_mean_log10_difference)}};
  j["capture"] = {{"rows_analysed", table.rows_analysed},
                  {"rows_without_speed", table.rows_without_speed},
                  {"blocks_dropped", table.blocks_dropped}};
  return j;
}

void write_comparison_json(const std::filesystem::path& file, const std::string& tool,
                           const std::string& surface, const ComparisonTable& table,
                           const LiveComparisonSettings& settings) {
  model::io::write_file_atomically(file,
                                   comparison_json(tool, surface, table, settings).dump(2) + "\n");
}

}  // namespace nibrig::rig
