// The real-time part of `nibrig demo`: every bundled tool that has a vibration spectrum, on one
// surface, rendered through the real-time engine over one sweep of the rig (17 → 250 → 17 mm/s)
// into <report>/render/*.wav, then played one after another when an audio device is present.
// Returns its lines for SUMMARY.txt and its numbers for SUMMARY.json.
#pragma once

#include <filesystem>
#include <string>

#include "model/io/catalog_file.hpp"
#include "ui/cli/demo_section.hpp"

namespace nibrig::ui::cli {

DemoSection run_render_demo(const model::io::Catalog& catalog,
                            const std::filesystem::path& catalog_file,
                            const std::filesystem::path& report);

}  // namespace nibrig::ui::cli
