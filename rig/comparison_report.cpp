#include "rig/comparison_report.hpp"

namespace nibrig::rig {

model::io::ComparisonFile comparison_report(const std::string& tool, const std::string& surface,
                                            const ComparisonTable& table,
                                            const LiveComparisonSettings& settings) {
  model::io::ComparisonFile c;
  c.tool = tool;
  c.surface = surface;
  c.sample_rate_hz = settings.acceleration_rate_hz;
  c.segment_length = settings.spectrogram.segment_length;
  c.hop = settings.spectrogram.hop;
  c.window = settings.spectrogram.window == model::measure::Window::hann ? "hann" : "rectangular";
  c.band_min_hz = settings.comparison.min_frequency_hz;
  c.band_max_hz = settings.comparison.max_frequency_hz;
  for (const auto& b : table.bins)
    c.bins.push_back({b.min_speed_m_s, b.max_speed_m_s, b.mean_speed_m_s, b.rows, b.lsd_db,
                      b.measured_weighted_mean, b.simulated_weighted_mean,
                      b.weighted_mean_log10_difference});
  c.bins_with_rows = table.summary.bins_with_rows;
  c.rows = table.summary.rows;
  c.rows_outside_speed_range = table.summary.rows_outside_speed_range;
  c.mean_lsd_db = table.summary.mean_lsd_db;
  c.mean_weighted_mean_log10_difference = table.summary.mean_weighted_mean_log10_difference;
  c.rows_analysed = table.rows_analysed;
  c.rows_without_speed = table.rows_without_speed;
  c.blocks_dropped = table.blocks_dropped;
  return c;
}

}  // namespace nibrig::rig
