#include "model/io/user_cache.hpp"

#include <bit>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "model/io/bounded_read.hpp"
#include "model/io/bundled_assets.hpp"
#include "model/io/json_fields.hpp"

namespace nibrig::model::io {

std::filesystem::path user_cache_dir() {
  if (const char* d = std::getenv("NIBRIG_CACHE"); d && *d) return d;
  if (const char* d = std::getenv("XDG_CACHE_HOME"); d && *d) return std::filesystem::path(d) / "nibrig";
  const char* home = std::getenv("HOME");
  return std::filesystem::path(home && *home ? home : ".") / ".cache" / "nibrig";
}

std::filesystem::path shipped_cache_dir() {
  if (const char* d = std::getenv("NIBRIG_SHIPPED_CACHE")) return d;
  if (const auto share = installed_share_dir(); !share.empty()) return share / "defaults";
#ifdef NIBRIG_SHIPPED_CACHE_DIR
  return NIBRIG_SHIPPED_CACHE_DIR;
#else
  return {};
#endif
}

std::filesystem::path shipped_twin(const std::filesystem::path& user_cache_file) {
  const auto shipped = shipped_cache_dir();
  if (shipped.empty() || user_cache_file.parent_path() != user_cache_dir()) return {};
  std::error_code error;
  if (std::filesystem::equivalent(shipped, user_cache_dir(), error)) return {};
  auto twin = shipped / user_cache_file.filename();
  return std::filesystem::is_regular_file(twin, error) ? twin : std::filesystem::path();
}

void CacheKey::mix(const void* data, std::size_t size) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) {
    hash_ ^= bytes[i];
    hash_ *= 0x100000001b3ull;
  }
}

CacheKey& CacheKey::add(std::string_view part) {
  const std::uint64_t size = part.size();
  mix(&size, sizeof size);
  mix(part.data(), part.size());
  return *this;
}

CacheKey& CacheKey::add(double value) {
  const auto bits = std::bit_cast<std::uint64_t>(value);
  mix(&bits, sizeof bits);
  return *this;
}

CacheKey& CacheKey::add(std::int64_t value) {
  mix(&value, sizeof value);
  return *this;
}

CacheKey& CacheKey::add_file(const std::filesystem::path& file) {
  return add(read_bounded_file(file, json_fields::kMaxJsonBytes, "an input file of a cached result",
                               "the bundled catalog is 1.3 MB"));
}

std::string CacheKey::hex() const {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash_));
  return text;
}

}  // namespace nibrig::model::io
