#include "ui/cli/mechanics_figures.hpp"

#include <complex>

#include "model/modal/frequency_response.hpp"
#include "ui/report/figures.hpp"

namespace nibrig::ui::cli {

void plot_frequency_responses(
    const std::vector<std::pair<std::string, model::modal::ModalModel>>& models,
    const std::string& title, const std::filesystem::path& png) {
  const std::vector<double> frequencies = model::modal::default_frequency_grid();
  report::LinePlot plot;
  plot.title = title;
  plot.x_label = "Frequency (Hz)";
  plot.y_label = "|H| tip force to sensor acceleration (m s#u-2#d N#u-1#d)";
  plot.log_y = true;
  for (const auto& [label, model] : models) {
    report::LineSeries series;
    series.label = label;
    series.x = frequencies;
    for (const auto& h : model::modal::frequency_response(model, frequencies))
      series.y.push_back(std::abs(h));
    plot.series.push_back(std::move(series));
  }
  report::write_line_plot(plot, png);
}

void plot_ring_down(const std::vector<double>& trace, const std::string& trace_label,
                    const std::vector<double>& fitted, double sample_rate, const std::string& title,
                    const std::filesystem::path& png) {
  report::LinePlot plot;
  plot.title = title;
  plot.x_label = "Time (s)";
  plot.y_label = "Acceleration (m s#u-2#d)";
  auto series_of = [&](const std::string& label, const std::vector<double>& values) {
    report::LineSeries series;
    series.label = label;
    series.y = values;
    for (std::size_t i = 0; i < values.size(); ++i)
      series.x.push_back(static_cast<double>(i) / sample_rate);
    return series;
  };
  plot.series.push_back(series_of(trace_label, trace));
  plot.series.push_back(series_of("fitted model", fitted));
  report::write_line_plot(plot, png);
}

}  // namespace nibrig::ui::cli
