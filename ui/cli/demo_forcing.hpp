// The forcing-model and design part of `nibrig demo` (Sec. 5.2-6.2): the fit of Eq. 10 to the
// bundled printed tools with its leave-one-out summary, the 2 mm tools predicted from the 1 and
// 4 mm ones, a predicted design between two printed ones, and a design search in the demo's
// (simulated-observer) space. The designs use 32 modes on a 4 mm mesh, not the template's 64 on
// 3 mm: |H| changes by ~1 % and the part runs in seconds; `nibrig forcing fit` uses the full
// template. Writes into <report>/forcing/ and returns its lines for SUMMARY.txt and its numbers
// for SUMMARY.json.
#pragma once

#include <filesystem>
#include <string>

#include "ui/cli/demo_section.hpp"


namespace nibrig::ui::cli {

DemoSection run_forcing_demo(const std::filesystem::path& catalog_file,
                             const std::filesystem::path& report);

}  // namespace nibrig::ui::cli
