// The rig part of `nibrig demo`: the simulated rig with vero2 on office, captured over the paper's
// three sweeps of speed steps and measured as any session (against its catalog spectrum), then
// compared live with its simulation over the study's sweep, with the comparison's report and
// figure in <report>/rig/. Returns its lines for SUMMARY.txt and its numbers for SUMMARY.json.
#pragma once

#include <filesystem>
#include <string>

#include "ui/cli/demo_section.hpp"

namespace nibrig::ui::cli {

DemoSection run_rig_demo(const std::filesystem::path& catalog_file, const std::filesystem::path& report);

}  // namespace nibrig::ui::cli
