#include "ui/cli/interpolation_report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <utility>
#include <vector>

#include "model/design/predicted_tool.hpp"
#include "ui/report/figures.hpp"

namespace nibrig::ui::cli {

namespace {

namespace design = model::design;
namespace forcing = model::forcing;

}  // namespace

std::string corner_name(const design::DesignPoint& corner) {
  return corner.mix.front().material + " " + forcing::tip_label(corner.tip_diameter_m);
}

std::string comparison_table(const design::InterpolationComparison& c,
                             std::span<const double> speeds_m_s) {
  std::string out = fmt::format("  {:>12} {:>13}", "speed (mm/s)", "interpolated");
  for (const auto& b : c.baselines) out += fmt::format(" {:>13}", corner_name(b.corner));
  out += "\n";
  for (std::size_t s = 0; s < speeds_m_s.size(); ++s) {
    out += fmt::format("  {:>12.1f} {:>13.2f}", speeds_m_s[s] * 1e3,
                       c.interpolated.rms_db_by_speed[s]);
    for (const auto& b : c.baselines) out += fmt::format(" {:>13.2f}", b.error.rms_db_by_speed[s]);
    out += "\n";
  }
  out += fmt::format("  {:>12} {:>13.2f}", "all", c.interpolated.rms_db);
  for (const auto& b : c.baselines) out += fmt::format(" {:>13.2f}", b.error.rms_db);
  return out + "\n";
}

void write_interpolation_figure(const forcing::ForcingModel& model,
                                const design::DesignPoint& point, const std::string& surface,
                                std::span<const double> response_magnitude,
                                const std::string& label,
                                const model::io::VelocitySpectrum& measured,
                                const std::filesystem::path& png) {
  const auto predicted = design::predict_spectrum(model, point, surface, response_magnitude);
  std::vector<std::pair<std::string, model::io::VelocitySpectrum>> baselines;
  for (const auto& corner : design::no_interpolation_corners(model, point))
    baselines.emplace_back("no interpolation: " + corner_name(corner),
                           design::predict_spectrum(model, corner, surface, response_magnitude));
  report::LinePanels figure;
  figure.title = fmt::format("{} on {}: predicted vs {}", design::label(point), surface, label);
  for (std::size_t s = 0; s < predicted.speeds_m_s.size(); ++s) {
    const double v = predicted.speeds_m_s[s];
    const std::size_t m = model::io::nearest_speed_row(measured, v);
    report::LinePlot panel;
    panel.title = std::abs(measured.speeds_m_s[m] - v) < 5e-4
                      ? fmt::format("{:.0f} mm/s", v * 1e3)
                      : fmt::format("{:.0f} mm/s (measured at {:.0f})", v * 1e3,
                                    measured.speeds_m_s[m] * 1e3);
    panel.x_label = "Frequency (Hz)";
    panel.y_label = "Amplitude (m/s²)";
    panel.log_y = true;
    panel.series.push_back(
        {"measured", measured.frequencies_hz, measured.amplitude_m_s2[m], {}, {}});
    panel.series.push_back(
        {"predicted", predicted.frequencies_hz, predicted.amplitude_m_s2[s], {}, {}});
    for (const auto& [name, spectrum] : baselines)
      panel.series.push_back(
          {name, spectrum.frequencies_hz, spectrum.amplitude_m_s2[s], {}, {}, /*muted=*/true});
    figure.panels.push_back(std::move(panel));
  }
  figure.size = {1800, figure.panels.size() > 3 ? 1100 : 700};
  report::write_line_panels(figure, png);
}

}  // namespace nibrig::ui::cli
