#include "ui/cli/forcing_figures.hpp"

#include <fmt/format.h>

#include <functional>

#include "model/forcing/hermite_curve.hpp"
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

// The 95 % band of a curve from its jackknife replicates: the curve's value ±1.96 standard errors
// at each frequency (the Hermite curve is linear in its knots, so each replicate's value is exact).
void add_band(
    report::LineSeries& series, const model::forcing::ForcingModel& model,
    const model::forcing::CurveJackknife& jackknife,
    const std::function<const std::vector<double>&(const model::forcing::CurveReplicate&)>&
        knots_of) {
  namespace forcing = model::forcing;
  for (std::size_t i = 0; i < series.x.size(); ++i) {
    const double f = series.x[i];
    const double se = jackknife.standard_error([&](const forcing::CurveReplicate& r) {
      return forcing::log_gain_to_db(
          forcing::hermite_value(model.knot_frequencies_hz, knots_of(r), f));
    });
    series.y_low.push_back(series.y[i] - 1.96 * se);
    series.y_high.push_back(series.y[i] + 1.96 * se);
  }
}

}  // namespace

void plot_scaling_curves(const model::forcing::ForcingModel& model,
                         const std::filesystem::path& folder,
                         const model::forcing::CurveJackknife* jackknife) {
  namespace forcing = model::forcing;
  const bool bands = jackknife != nullptr && jackknife->replicates.size() >= 2;
  const std::string band_note =
      bands ? fmt::format(" (95 % bands: jackknife over {} tools)", jackknife->replicates.size())
            : std::string();
  const auto frequencies = curve_frequencies(model);
  report::LinePlot tips;
  tips.title = fmt::format("Tip scaling t(f), relative to the {:g} mm tip{}",
                           model.reference_tip_diameter_m * 1e3, band_note);
  tips.x_label = "Frequency (Hz)";
  tips.y_label = "Gain (dB)";
  for (const auto& [diameter, curve] : model.tip_log_gain) {
    report::LineSeries series;
    series.label = fmt::format("{:g} mm", diameter * 1e3);
    series.x = frequencies;
    for (double f : frequencies)
      series.y.push_back(forcing::log_gain_to_db(model.tip_log_gain_at(diameter, f)));
    if (bands)
      add_band(series, model, *jackknife,
               [d = diameter](const forcing::CurveReplicate& r) -> const std::vector<double>& {
                 return r.tip.at(d);
               });
    tips.series.push_back(std::move(series));
  }
  report::write_line_plot(tips, folder / "tip_curves.png");

  report::LinePlot materials;
  materials.title =
      fmt::format("Material scaling m(f), relative to {}{}", model.reference_material, band_note);
  materials.x_label = "Frequency (Hz)";
  materials.y_label = "Gain (dB)";
  for (const auto& [name, curve] : model.material_log_gain) {
    report::LineSeries series;
    series.label = name;
    series.x = frequencies;
    for (double f : frequencies)
      series.y.push_back(forcing::log_gain_to_db(model.material_log_gain_at(name, f)));
    if (bands)
      add_band(series, model, *jackknife,
               [m = name](const forcing::CurveReplicate& r) -> const std::vector<double>& {
                 return r.material.at(m);
               });
    materials.series.push_back(std::move(series));
  }
  report::write_line_plot(materials, folder / "material_curves.png");
}

}  // namespace nibrig::ui::cli
