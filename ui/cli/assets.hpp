// Where the bundled assets (default catalog, threshold curve) are: $NIBRIG_ASSETS, else the
// repository's assets/ folder this binary was built from.
#pragma once

#include <filesystem>

namespace nibrig::ui::cli {

std::filesystem::path assets_dir();

// assets_dir() / relative, or a clear error naming what is missing and how to point at it.
std::filesystem::path asset(const std::filesystem::path& relative);

// The detection threshold the catalog's descriptors are weighted by unless told otherwise (Israr
// et al. 2006, pen hold).
std::filesystem::path default_threshold_curve();

}  // namespace nibrig::ui::cli
