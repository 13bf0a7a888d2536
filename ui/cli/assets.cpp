#include "ui/cli/assets.hpp"

#include <cstdlib>
#include <stdexcept>

namespace nibrig::ui::cli {

std::filesystem::path assets_dir() {
  if (const char* env = std::getenv("NIBRIG_ASSETS"); env != nullptr && *env != '\0') return env;
  return std::filesystem::path(NIBRIG_SOURCE_DIR) / "assets";
}

std::filesystem::path asset(const std::filesystem::path& relative) {
  const auto path = assets_dir() / relative;
  if (!std::filesystem::exists(path)) {
    throw std::runtime_error("bundled asset not found: " + path.string() +
                             " (set NIBRIG_ASSETS to the assets/ folder of a nibrig checkout)");
  }
  return path;
}

std::filesystem::path default_threshold_curve() {
  return asset("thresholds/israr2006_pen_hold.csv");
}

}  // namespace nibrig::ui::cli
