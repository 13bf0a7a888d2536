// How a design's prediction compares with a measurement and with the no-interpolation baselines of
// Fig. 14, for people: the table of RMS errors per speed and the figure. Shared by `nibrig predict`
// (a design against a measurement) and `nibrig forcing holdout` (measured designs the fit never saw).
#pragma once

#include <filesystem>
#include <span>
#include <string>

#include "model/design/design_point.hpp"
#include "model/design/no_interpolation_baseline.hpp"
#include "model/forcing/forcing_model.hpp"
#include "model/io/velocity_spectrum.hpp"

namespace nibrig::ui::cli {

// "DM85 4 mm": whose scalings a no-interpolation baseline used.
std::string corner_name(const model::design::DesignPoint& corner);

// One row per speed and one for all: the prediction's RMS dB, then each baseline's.
std::string comparison_table(const model::design::InterpolationComparison& c,
                             std::span<const double> speeds_m_s);

// Like Fig. 14: a panel per speed of the model with the measurement (its nearest speed, said in
// the panel title when not the same), the point's prediction from `response_magnitude`, and the
// no-interpolation baselines muted in grey under them.
void write_interpolation_figure(const model::forcing::ForcingModel& model,
                                const model::design::DesignPoint& point, const std::string& surface,
                                std::span<const double> response_magnitude,
                                const std::string& measured_label,
                                const model::io::VelocitySpectrum& measured,
                                const std::filesystem::path& png);

}  // namespace nibrig::ui::cli
