// The mechanics part of `nibrig demo`: the bar validation (FEM against Euler-Bernoulli under mesh
// refinement, the paper's bar and a ring-down fit) and the frequency responses of the bundled
// stylus designs. Writes into <report>/mechanics/ and returns its lines for SUMMARY.txt and its
// numbers for SUMMARY.json.
#pragma once

#include <filesystem>
#include <string>

#include "ui/cli/demo_section.hpp"

namespace nibrig::ui::cli {

DemoSection run_mechanics_demo(const std::filesystem::path& report);

}  // namespace nibrig::ui::cli
