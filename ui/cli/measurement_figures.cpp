#include "ui/cli/measurement_figures.hpp"

#include <algorithm>
#include <cstdio>

#include "ui/report/figures.hpp"

namespace nibrig::ui::cli {

namespace report = nibrig::ui::report;

namespace {

std::string speed_label(double speed_m_s) {
  char text[32];
  std::snprintf(text, sizeof text, "%.0f mm/s", speed_m_s * 1000.0);
  return text;
}

// The paper reports μ between 0.13 and 0.33 over its tool-surface pairs (Sec. 3.3).
constexpr double paper_mu_low = 0.13;
constexpr double paper_mu_high = 0.33;

}  // namespace

void plot_velocity_spectrum(const model::io::VelocitySpectrum& spectrum, const std::string& title,
                            const std::filesystem::path& png) {
  report::HeatMap map;
  map.x = spectrum.frequencies_hz;
  for (double v : spectrum.speeds_m_s) map.y.push_back(v * 1000.0);
  map.z = spectrum.amplitude_m_s2;
  map.title = title;
  map.x_label = "frequency (Hz)";
  map.y_label = "speed (mm/s)";
  map.colour_label = "amplitude (dB re max)";
  map.log_colour = true;
  report::write_heat_map(map, png);
}

void plot_spectra_by_speed(const model::io::VelocitySpectrum& spectrum, const std::string& title,
                           const std::filesystem::path& png) {
  report::LinePlot plot;
  plot.title = title;
  plot.x_label = "frequency (Hz)";
  plot.y_label = "amplitude (m/s#u2#d)";
  plot.log_y = true;
  for (std::size_t s = 0; s < spectrum.speeds_m_s.size(); ++s) {
    report::LineSeries series;
    series.label = speed_label(spectrum.speeds_m_s[s]);
    series.x = spectrum.frequencies_hz;
    series.y = spectrum.amplitude_m_s2[s];
    // A log axis cannot show zeros: they are drawn at the smallest positive amplitude of the curve.
    double smallest = 0.0;
    for (double a : series.y) {
      if (a > 0.0 && (smallest == 0.0 || a < smallest)) smallest = a;
    }
    for (double& a : series.y) a = std::max(a, smallest);
    plot.series.push_back(std::move(series));
  }
  report::write_line_plot(plot, png);
}

void plot_spectrogram(const model::measure::Spectrogram& spectrogram, const std::string& title,
                      const std::filesystem::path& png) {
  report::HeatMap map;
  map.x = spectrogram.times_s;
  map.y = spectrogram.frequencies_hz;
  // HeatMap wants z[y][x]: frequency rows, time columns.
  map.z.assign(map.y.size(), std::vector<double>(map.x.size()));
  for (std::size_t t = 0; t < map.x.size(); ++t) {
    for (std::size_t f = 0; f < map.y.size(); ++f) {
      map.z[f][t] =
          spectrogram.amplitude(static_cast<Eigen::Index>(t), static_cast<Eigen::Index>(f));
    }
  }
  map.title = title;
  map.x_label = "time (s)";
  map.y_label = "frequency (Hz)";
  map.colour_label = "amplitude (dB re max)";
  map.log_colour = true;
  report::write_heat_map(map, png);
}

void plot_mu_by_speed(const model::catalog::FrictionAnalysis& analysis,
                      const std::filesystem::path& png) {
  report::LinePlot plot;
  plot.title = "Friction of " + analysis.tool + " on " + analysis.surface + " against speed";
  plot.x_label = "speed (mm/s, assumed linear sweep)";
  plot.y_label = "friction coefficient #gm";
  report::LineSeries by_speed;
  by_speed.label = "#gm per speed bin (95 % interval)";
  for (double v : analysis.fit.speeds_m_s) by_speed.x.push_back(v * 1000.0);
  by_speed.y = analysis.fit.mu_by_speed;
  by_speed.y_low = analysis.fit.mu_by_speed_ci_low;
  by_speed.y_high = analysis.fit.mu_by_speed_ci_high;
  report::LineSeries overall;
  overall.label = "Coulomb #gm over the contact";
  overall.x = {by_speed.x.front(), by_speed.x.back()};
  overall.y = {analysis.fit.mu, analysis.fit.mu};
  overall.y_low = {analysis.fit.mu_ci_low, analysis.fit.mu_ci_low};
  overall.y_high = {analysis.fit.mu_ci_high, analysis.fit.mu_ci_high};
  plot.series = {by_speed, overall};
  report::write_line_plot(plot, png);
}

void plot_friction_trace(const model::catalog::FrictionAnalysis& analysis,
                         const std::filesystem::path& png) {
  report::LinePlot plot;
  plot.title = "Tangential force / normal load: " + analysis.tool + " on " + analysis.surface;
  plot.x_label = "time (s)";
  plot.y_label = "F#dt#u / F#dn#u";
  // Decimate to about 4000 points: the figure cannot show more, and PLplot slows down with 60k.
  const std::size_t n = analysis.tangential_force_N.size();
  const std::size_t stride = std::max<std::size_t>(1, n / 4000);
  report::LineSeries trace{.label = "measured", .x = {}, .y = {}, .y_low = {}, .y_high = {}};
  for (std::size_t i = 0; i < n; i += stride) {
    trace.x.push_back(static_cast<double>(i) / analysis.sample_rate_hz);
    trace.y.push_back(analysis.tangential_force_N[i] / analysis.normal_load_N);
  }
  const double begin = static_cast<double>(analysis.fit.contact.begin) / analysis.sample_rate_hz;
  const double end = static_cast<double>(analysis.fit.contact.end) / analysis.sample_rate_hz;
  report::LineSeries contact{.label = "detected contact, #gm",
                             .x = {begin, end},
                             .y = {analysis.fit.mu, analysis.fit.mu},
                             .y_low = {},
                             .y_high = {}};
  plot.series = {trace, contact};
  report::write_line_plot(plot, png);
}

void plot_catalog_friction(const model::io::Catalog& catalog, const std::filesystem::path& png) {
  report::IntervalChart chart;
  chart.title = "Coulomb friction per tool and surface (95 % intervals)";
  chart.value_label = "#gm";
  chart.reference_band = std::make_pair(paper_mu_low, paper_mu_high);
  chart.reference_label = "range reported in the paper (0.13-0.33)";
  std::vector<const model::io::Pairing*> pairs;
  for (const auto& p : catalog.pairings) {
    if (p.friction) pairs.push_back(&p);
  }
  std::stable_sort(pairs.begin(), pairs.end(),
                   [](const auto* a, const auto* b) { return a->surface < b->surface; });
  for (const auto* p : pairs) {
    chart.bars.push_back({.label = p->tool + " / " + p->surface,
                          .value = p->friction->mu,
                          .low = p->friction->mu_ci_low,
                          .high = p->friction->mu_ci_high,
                          .group = p->surface});
  }
  report::write_interval_chart(chart, png);
}

}  // namespace nibrig::ui::cli
