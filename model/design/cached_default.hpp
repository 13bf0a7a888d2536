// What a face opens on without asking (a default space and forcing model): the inputs
// and the progress and cancel hooks every default takes, and the one way each is kept in the user
// cache (model/io/user_cache.hpp): read when a file of its key is there and readable, else
// computed, then stored atomically under that key.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <spdlog/spdlog.h>

#include "model/io/user_cache.hpp"
#include "model/numeric/cancellation.hpp"
#include "model/numeric/progress_counter.hpp"

namespace nibrig::model::design {

struct DefaultsOptions {
  std::filesystem::path cache_dir;  // empty: io::user_cache_dir()
  // The inputs; empty: the bundled ones (model/io/bundled_assets.hpp).
  std::filesystem::path catalog, threshold_curve, materials, stylus_design;
  // The space's bootstrap refits: the demo's 200; fewer only where time matters more than the
  // regions (tests). Part of the key.
  int bootstrap_resamples = 200;
  unsigned threads = 0;  // 0: one per core; no result depends on it
  // Called only while computing: a default read from the cache reports nothing. Called from
  // worker threads, never two at once: a window posts it to its own thread.
  numeric::StepProgress progress;
  // Stops the computation with numeric::Cancelled; nothing is stored then.
  std::stop_token stop;
};

template <typename T>
struct Cached {
  T value;
  std::filesystem::path file;  // where it is kept (it may not be there: see warnings)
  bool computed = false;       // false: read from the cache
  // A cache file that could not be read (and was replaced), or one that could not be written:
  // neither stops a face, both are worth a line in it. Also logged.
  std::vector<std::string> warnings;
};

// `dir`/<name>-<16 hex digits of the key>.json: a file per key, so a stale result is never read,
// only left behind.
inline std::filesystem::path cache_file(const std::filesystem::path& dir, const std::string& name,
                                        const io::CacheKey& key) {
  return dir / (name + "-" + key.hex() + ".json");
}

// read(file) -> T throws on a file it cannot take; compute() -> T; write(file, value) writes
// atomically (the format writers do). `what` names the result in warnings ("default space").
// A file of the user cache missing there is read from the shipped layer (io::shipped_twin) when
// the build computed it.
template <typename T, typename Read, typename Compute, typename Write>
Cached<T> cached_default(const std::filesystem::path& file, const std::string& what, Read read,
                         Compute compute, Write write) {
  Cached<T> out;
  out.file = file;
  std::error_code error;
  for (const auto& candidate : {file, io::shipped_twin(file)}) {
    if (candidate.empty() || !std::filesystem::exists(candidate, error)) continue;
    try {
      out.value = read(candidate);
      out.file = candidate;
      return out;
    } catch (const std::exception& e) {
      // A file cut short by a full disk, edited by hand or from an older build: computing again
      // costs time, failing would cost the face.
      out.warnings.push_back(candidate.string() + ": the cached " + what + " cannot be read (" +
                             e.what() + "); computing it again");
      spdlog::warn("{}", out.warnings.back());
    }
  }
  out.value = compute();
  out.computed = true;
  try {
    std::filesystem::create_directories(file.parent_path());
    write(file, out.value);
  } catch (const std::exception& e) {
    out.warnings.push_back(file.string() + ": the " + what + " was computed but cannot be kept (" +
                           e.what() + "); it will be computed again next time");
    spdlog::warn("{}", out.warnings.back());
  }
  return out;
}

}  // namespace nibrig::model::design
