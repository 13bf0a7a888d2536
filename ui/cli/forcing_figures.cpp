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

using KnotsOf = std::function<const std::vector<double>&(const model::forcing::CurveReplicate&)>;

// One fitted curve (its knot values) in dB at `frequencies`; with a jackknife, its 95 % band: the
// value ±1.96 standard errors at each frequency (the Hermite curve is linear in its knots, so each
// replicate's value there is exact).
report::LineSeries curve_series(std::string label, const std::vector<double>& knots,
                                const std::vector<double>& frequencies,
                                const model::forcing::ForcingModel& model,
                                const model::forcing::CurveJackknife* jackknife,
                                const KnotsOf& knots_of) {
  namespace forcing = model::forcing;
  report::LineSeries series;
  series.label = std::move(label);
  series.x = frequencies;
  for (double f : frequencies)
    series.y.push_back(
        forcing::log_gain_to_db(forcing::hermite_value(model.knot_frequencies_hz, knots, f)));
  if (jackknife == nullptr) return series;
  for (std::size_t i = 0; i < frequencies.size(); ++i) {
    const double se = jackknife->standard_error([&](const forcing::CurveReplicate& r) {
      return forcing::log_gain_to_db(
          forcing::hermite_value(model.knot_frequencies_hz, knots_of(r), frequencies[i]));
    });
    series.y_low.push_back(series.y[i] - 1.96 * se);
    series.y_high.push_back(series.y[i] + 1.96 * se);
  }
  return series;
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
  const forcing::CurveJackknife* with_bands = bands ? jackknife : nullptr;
  for (const auto& [diameter, knots] : model.tip_log_gain)
    tips.series.push_back(curve_series(
        fmt::format("{:g} mm", diameter * 1e3), knots, frequencies, model, with_bands,
        [d = diameter](const forcing::CurveReplicate& r) -> const std::vector<double>& {
          return r.tip.at(d);
        }));
  report::write_line_plot(tips, folder / "tip_curves.png");

  report::LinePlot materials;
  materials.title =
      fmt::format("Material scaling m(f), relative to {}{}", model.reference_material, band_note);
  materials.x_label = "Frequency (Hz)";
  materials.y_label = "Gain (dB)";
  for (const auto& [name, knots] : model.material_log_gain)
    materials.series.push_back(
        curve_series(name, knots, frequencies, model, with_bands,
                     [m = name](const forcing::CurveReplicate& r) -> const std::vector<double>& {
                       return r.material.at(m);
                     }));
  report::write_line_plot(materials, folder / "material_curves.png");
}

}  // namespace nibrig::ui::cli
