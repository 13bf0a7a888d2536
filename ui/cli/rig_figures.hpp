// How `nibrig rig compare` shows a comparison: the per-speed table on stdout and the figure of the
// measured, simulated and difference spectrograms (ui/report).
#pragma once

#include <filesystem>
#include <string>

#include "rig/comparison_run.hpp"

namespace nibrig::ui::cli {

// One line per speed bin: its range, rows, log-spectral distance and weighted-mean difference.
void print_comparison_table(const rig::ComparisonTable& table);

// measured | simulated | difference over time, up to 500 Hz, from every row of the run.
void write_comparison_figure(const rig::ComparisonRun& run, const std::string& title,
                             const std::filesystem::path& png);

}  // namespace nibrig::ui::cli
