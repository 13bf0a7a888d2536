// The mechanics part of `nibrig demo`: the bar validation (FEM against Euler-Bernoulli under mesh
// refinement, the paper's bar and a ring-down fit) and the frequency responses of the bundled
// stylus designs. Writes into <report>/mechanics/ and returns its lines for SUMMARY.txt and its
// numbers for SUMMARY.json.
#pragma once

#include <filesystem>
#include <string>

#include "ui/cli/demo_section.hpp"

namespace nibrig::ui::cli {

// progress_bar: false when another part runs beside it and owns the terminal's progress line.
DemoSection run_mechanics_demo(const std::filesystem::path& report, bool progress_bar = true);

}  // namespace nibrig::ui::cli
