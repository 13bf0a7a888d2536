// Figures of the forcing model: the tip and material scaling curves over 0-500 Hz in dB, one
// curve per tip diameter and per material (the paper's Fig. 13).
#pragma once

#include <filesystem>

#include "model/forcing/curve_jackknife.hpp"
#include "model/forcing/forcing_model.hpp"

namespace nibrig::ui::cli {

// Writes folder/tip_curves.png and folder/material_curves.png; with a jackknife of the fit, each
// curve with its 95 % band (±1.96 standard errors).
void plot_scaling_curves(const model::forcing::ForcingModel& model,
                         const std::filesystem::path& folder,
                         const model::forcing::CurveJackknife* jackknife = nullptr);

}  // namespace nibrig::ui::cli
