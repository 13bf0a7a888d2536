// Figures of the mechanics: a tool's frequency response from tip force to sensor acceleration,
// and a ring-down test, measured against simulated (the paper's Fig. 11).
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "model/modal/modal_model.hpp"

namespace nibrig::ui::cli {

// |H(f)| over 1-500 Hz on a log scale, one curve per (label, model).
void plot_frequency_responses(
    const std::vector<std::pair<std::string, model::modal::ModalModel>>& models,
    const std::string& title, const std::filesystem::path& png);

// Acceleration over time: the trace that was fitted (labelled `trace_label`: "measured", or what
// stands in for a measurement) and the fitted model.
void plot_ring_down(const std::vector<double>& trace, const std::string& trace_label,
                    const std::vector<double>& fitted, double sample_rate, const std::string& title,
                    const std::filesystem::path& png);

}  // namespace nibrig::ui::cli
