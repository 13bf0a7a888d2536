#include "model/io/bundled_assets.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <stdexcept>

namespace nibrig::model::io {

std::filesystem::path installed_share_dir() {
  // Found from the file this code was loaded from: <prefix>/bin/nibrig, or the Python module's
  // <prefix>/lib/python3/dist-packages/nibrig/_core.so, a few folders below <prefix>.
  static const std::filesystem::path found = [] {
    std::error_code error;
    std::filesystem::path object;
    Dl_info info{};
    if (dladdr(reinterpret_cast<void*>(&installed_share_dir), &info) != 0 &&
        info.dli_fname != nullptr)
      object = info.dli_fname;
    if (!object.is_absolute()) object = std::filesystem::read_symlink("/proc/self/exe", error);
    if (error || object.empty()) return std::filesystem::path();
    auto folder = object.parent_path();
    for (int up = 0; up < 5 && folder.has_relative_path(); ++up, folder = folder.parent_path()) {
      const auto share = folder.parent_path() / "share" / "nibrig";
      if (std::filesystem::is_directory(share / "assets", error)) return share;
    }
    return std::filesystem::path();
  }();
  return found;
}

std::filesystem::path assets_dir() {
  if (const char* env = std::getenv("NIBRIG_ASSETS"); env != nullptr && *env != '\0') return env;
  if (const auto share = installed_share_dir(); !share.empty()) return share / "assets";
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

std::filesystem::path default_catalog() { return asset("default_catalog.json"); }
std::filesystem::path default_materials() { return asset("materials.json"); }
std::filesystem::path default_stylus_design() { return asset("designs/stylus_vero_tip2mm.json"); }
std::filesystem::path default_threshold_curve() {
  return asset("thresholds/israr2006_pen_hold.csv");
}

std::filesystem::path or_default(const std::filesystem::path& path,
                                 std::filesystem::path (*fallback)()) {
  return path.empty() ? fallback() : path;
}

}  // namespace nibrig::model::io
