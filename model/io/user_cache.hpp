// Where results that take seconds to compute and depend only on their inputs are kept between runs
// (the default space and forcing model, the design-response grid), and the keys that say
// which inputs they were computed from: a result is reused only when every input is byte-equal.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace nibrig::model::io {

// $NIBRIG_CACHE, else $XDG_CACHE_HOME/nibrig, else ~/.cache/nibrig (not created here).
std::filesystem::path user_cache_dir();

// A read-only layer under the user cache: the bundled defaults computed when nibrig was built
// (`nibrig defaults`, run by the build into its defaults/ folder), each named as the user cache
// names it, so that a first start finds them at once. $NIBRIG_SHIPPED_CACHE when set (empty: none),
// else an installed program's share/nibrig/defaults (bundled_assets.hpp), else the folder the build
// filled; empty for a build made without them. Never written to.
std::filesystem::path shipped_cache_dir();

// For a file in the user cache (directly in user_cache_dir()), its twin in the shipped layer when
// there is one; else empty. A file in any other folder has none: a cache a caller chose is its own.
std::filesystem::path shipped_twin(const std::filesystem::path& user_cache_file);

// Accumulates the inputs of a cached result; hex() names it. 64-bit FNV-1a over each part's length
// and bytes, so that ("ab","c") and ("a","bc") differ. Not cryptographic: it tells a stale cache
// from a fresh one, nothing more.
class CacheKey {
 public:
  CacheKey& add(std::string_view part);
  CacheKey& add(double value);  // its exact bits
  CacheKey& add(std::int64_t value);
  // The file's whole content; throws std::runtime_error naming the file when it cannot be read.
  CacheKey& add_file(const std::filesystem::path& file);
  std::string hex() const;  // 16 lowercase hex digits

 private:
  void mix(const void* data, std::size_t size);
  std::uint64_t hash_ = 0xcbf29ce484222325ull;
};

}  // namespace nibrig::model::io
