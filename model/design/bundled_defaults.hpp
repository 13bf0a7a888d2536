// What the faces compute on first use from the bundled inputs alone, computed ahead: the build runs
// it (`nibrig defaults` into its defaults/ folder, the shipped layer of io::shipped_cache_dir), so
// that the panel and the commands start at once on the bundled default; a lab's own inputs still
// go through the user cache as before.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "model/design/cached_default.hpp"

namespace nibrig::model::design {

struct BundledDefault {
  std::string what;  // "default space", ...
  std::filesystem::path
      file;  // where it is kept (the user cache, or the shipped layer it was read from)
  bool computed = false;  // false: it was there already
  double seconds = 0.0;   // to compute or read it
};

// In order: the default space (options' bootstrap count), the default forcing model at the panel's
// resolution (ForcingResolution{}) and at the stylus template's own (the commands' without
// --forcing), the bundled stylus's modes (the panel's tool sounds), and the design grid over
// vero-DM85 × the fitted tips at the default density (kDefaultFractionPoints × kDefaultTipPoints,
// at the template's resolution: the panel's Design view and `design --grid`). Each into the user
// cache (options.cache_dir must be empty: the grid's cache is always the user's), as its own cache
// keeps it, read instead when it is there. `options.progress` names each step; a stop throws
// numeric::Cancelled. Throws std::invalid_argument for a cache_dir given, and what each default
// throws.
std::vector<BundledDefault> compute_bundled_defaults(const DefaultsOptions& options = {});

}  // namespace nibrig::model::design
