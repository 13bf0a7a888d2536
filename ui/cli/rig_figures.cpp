#include "ui/cli/rig_figures.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "ui/report/figures.hpp"

namespace nibrig::ui::cli {
namespace {

// Drawn up to here: the tools are rendered to 500 Hz (the paper's band, where the comparison's
// distances are taken); above it there is only the rig's noise floor to tell apart.
constexpr double kFigureTopHz = 500.0;

}  // namespace

void print_comparison_table(const rig::ComparisonTable& table) {
  std::printf("speed bin (mm/s)   rows   distance (dB)   weighted mean, simulated/measured\n");
  for (const auto& b : table.bins) {
    if (b.rows == 0) continue;
    std::printf("%6.1f - %6.1f  %6zu   %8.2f        %+7.1f %%\n", b.min_speed_m_s * 1e3,
                b.max_speed_m_s * 1e3, b.rows, b.lsd_db,
                100.0 * (std::pow(10.0, b.weighted_mean_log10_difference) - 1.0));
  }
  const auto& s = table.summary;
  std::printf("over %zu speed bins: mean distance %.2f dB, weighted mean %+.1f %%; %llu rows "
              "analysed, %llu outside 17-250 mm/s, %llu blocks dropped\n",
              s.bins_with_rows, s.mean_lsd_db,
              100.0 * (std::pow(10.0, s.mean_weighted_mean_log10_difference) - 1.0),
              static_cast<unsigned long long>(table.rows_analysed),
              static_cast<unsigned long long>(s.rows_outside_speed_range),
              static_cast<unsigned long long>(table.blocks_dropped));
}

void write_comparison_figure(const rig::ComparisonRun& run, const std::string& title,
                             const std::filesystem::path& png) {
  const auto& rows = run.rows;
  const auto& frequencies = run.table.frequencies_hz;
  if (rows.rows() < 2) throw std::runtime_error("the comparison holds too few rows for a figure");
  report::ComparisonSpectrograms figure;
  figure.title = title;
  figure.x_label = "time (s)";
  figure.y_label = "frequency (Hz)";
  figure.x = rows.times_s;
  std::vector<std::size_t> kept;
  for (std::size_t k = 1; k < frequencies.size() && frequencies[k] <= kFigureTopHz; ++k) {
    kept.push_back(k);
    figure.y.push_back(frequencies[k]);
  }
  for (const std::size_t k : kept) {
    std::vector<double> measured(rows.rows()), simulated(rows.rows());
    for (std::size_t i = 0; i < rows.rows(); ++i) {
      measured[i] = rows.measured_db[i * rows.bins + k];
      simulated[i] = rows.simulated_db[i * rows.bins + k];
    }
    figure.measured_db.push_back(std::move(measured));
    figure.simulated_db.push_back(std::move(simulated));
  }
  report::write_comparison_spectrograms(figure, png);
}

}  // namespace nibrig::ui::cli
