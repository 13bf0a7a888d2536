// Adapters from the science's results to the report figures: which axes, labels and units each
// measurement is shown with. All figures are PNG files written by ui/report.
#pragma once

#include <filesystem>
#include <string>

#include "model/catalog/analysis.hpp"
#include "model/io/catalog_file.hpp"

namespace nibrig::ui::cli {

// Heat map of amplitude over frequency (x) and speed (y), in dB re the largest value.
void plot_velocity_spectrum(const model::io::VelocitySpectrum& spectrum, const std::string& title,
                            const std::filesystem::path& png);

// One amplitude-vs-frequency curve per speed.
void plot_spectra_by_speed(const model::io::VelocitySpectrum& spectrum, const std::string& title,
                           const std::filesystem::path& png);

// Short-time spectrogram of a whole recording, time on x.
void plot_spectrogram(const model::measure::Spectrogram& spectrogram, const std::string& title,
                      const std::filesystem::path& png);

// μ in each speed bin with its 95 % interval, and the overall μ.
void plot_mu_by_speed(const model::catalog::FrictionAnalysis& analysis,
                      const std::filesystem::path& png);

// The tangential force over the recording divided by the load, with the detected contact region.
void plot_friction_trace(const model::catalog::FrictionAnalysis& analysis,
                         const std::filesystem::path& png);

// μ with 95 % intervals for every pair in a catalog, grouped by surface, against the paper's range.
void plot_catalog_friction(const model::io::Catalog& catalog, const std::filesystem::path& png);

}  // namespace nibrig::ui::cli
