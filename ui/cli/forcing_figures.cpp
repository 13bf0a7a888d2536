#include "ui/cli/forcing_figures.hpp"

#include <fmt/format.h>

#include "ui/report/figures.hpp"

namespace nibrig::ui::cli {

namespace {

// 1 Hz steps between the first and last knot: the curves are smooth cubics, so this draws them
// exactly at any image size.
std::vector<double> curve_frequencies(const model::forcing::ForcingModel& model) {
  std::vector<double> f;
  for (double x = model.knot_frequencies_hz.front(); x <= model.knot_frequencies_hz.back(); x += 1)
    f.push_back(x);
  return f;
}

}  // namespace

void plot_scaling_curves(const model::forcing::ForcingModel& model,
                         const std::filesystem::path& folder) {
  namespace forcing = model::forcing;
  const auto frequencies = curve_frequencies(model);
  report::LinePlot tips;
  tips.title = fmt::format("Tip scaling t(f), relative to the {:g} mm tip",
                           model.reference_tip_diameter_m * 1e3);
  tips.x_label = "Frequency (Hz)";
  tips.y_label = "Gain (dB)";
  for (const auto& [diameter, curve] : model.tip_log_gain) {
    report::LineSeries series;
    series.label = fmt::format("{:g} mm", diameter * 1e3);
    series.x = frequencies;
    for (double f : frequencies)
      series.y.push_back(forcing::log_gain_to_db(model.tip_log_gain_at(diameter, f)));
    tips.series.push_back(std::move(series));
  }
  report::write_line_plot(tips, folder / "tip_curves.png");

  report::LinePlot materials;
  materials.title = fmt::format("Material scaling m(f), relative to {}", model.reference_material);
  materials.x_label = "Frequency (Hz)";
  materials.y_label = "Gain (dB)";
  for (const auto& [name, curve] : model.material_log_gain) {
    report::LineSeries series;
    series.label = name;
    series.x = frequencies;
    for (double f : frequencies)
      series.y.push_back(forcing::log_gain_to_db(model.material_log_gain_at(name, f)));
    materials.series.push_back(std::move(series));
  }
  report::write_line_plot(materials, folder / "material_curves.png");
}

}  // namespace nibrig::ui::cli
