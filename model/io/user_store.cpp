#include "model/io/user_store.hpp"

#include <cctype>
#include <cstdlib>

namespace nibrig::model::io {

std::filesystem::path user_store_folder(const char* override_variable, const std::string& kind) {
  if (const char* d = std::getenv(override_variable); d && *d) return d;
  if (const char* d = std::getenv("XDG_DATA_HOME"); d && *d) return std::filesystem::path(d) / "nibrig" / kind;
  const char* home = std::getenv("HOME");
  return std::filesystem::path(home && *home ? home : ".") / ".local" / "share" / "nibrig" / kind;
}

std::filesystem::path user_store_file(const std::filesystem::path& folder, const std::string& name,
                                      const std::string& fallback) {
  std::string safe = name;
  for (char& c : safe)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
  if (safe.empty() || safe == "." || safe == "..") safe = fallback;
  return folder / (safe + ".json");
}

}  // namespace nibrig::model::io
