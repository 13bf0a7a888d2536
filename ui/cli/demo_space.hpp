// The perceptual-space part of `nibrig demo`. No human judgments of drawing tools are bundled, so
// it runs a SIMULATED-OBSERVER study: an observer whose perception follows the catalog's own
// descriptors judges the paper's two-stage experiment on 15 tool-surface pairs; the judgments are
// fitted, cross-validated and bootstrapped, and every catalog tool is placed from its descriptors.
// Writes into <report>/space/ and returns its lines for SUMMARY.txt, which say it is simulated,
// and its numbers for SUMMARY.json.
#pragma once

#include <filesystem>
#include <string>

#include "model/io/catalog_file.hpp"
#include "ui/cli/demo_section.hpp"

namespace nibrig::ui::cli {

DemoSection run_space_demo(const model::io::Catalog& catalog,
                           const std::filesystem::path& catalog_file,
                           const std::filesystem::path& report, unsigned threads);

}  // namespace nibrig::ui::cli
