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
