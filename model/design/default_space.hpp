// The perceptual space a face opens on: the demo's simulated-observer study
// (model/space/simulated_study.hpp) on the bundled catalog, its vibration descriptors weighted by
// the bundled threshold curve as `nibrig demo` weighs them. Computed once (seconds, with progress)
// and kept in the user cache; and every tool to draw in it.
#pragma once

#include <filesystem>
#include <string>

#include "model/design/cached_default.hpp"
#include "model/io/catalog_file.hpp"
#include "model/io/user_cache.hpp"
#include "model/space/simulated_study.hpp"
#include "model/space/space_file.hpp"
#include "model/space/space_tools.hpp"

namespace nibrig::model::design {

// Bumped whenever the study or the space file changes what a key's file holds.
inline constexpr int kDefaultSpaceVersion = 1;

struct DefaultSpace {
  space::SpaceFile space;
  // The catalog as the study saw it (descriptors weighted by the threshold curve), which placing
  // the other tools needs, and the file it was read from.
  io::Catalog catalog;
  std::filesystem::path catalog_file;
};

// The study's options for these inputs: the demo's, with options' bootstrap count, threads,
// progress and cancel.
space::SimulatedStudyOptions default_study_options(const DefaultsOptions& options);

// Every input the space depends on: the key format version, the catalog's and the threshold
// curve's bytes, and every number of the study (not threads, progress or cancel). Throws
// std::runtime_error naming an input file that cannot be read.
io::CacheKey default_space_key(const DefaultsOptions& options = {});

// <cache>/default_space-<key>.json when it is there and reads as a space file; else the study
// runs (steps "space fit starts", "bootstrap refits") and its space is written there atomically.
// A cache file that does not read is computed again, with a warning. Throws what reading the
// catalog or the threshold curve throws (naming the file), what run_simulated_study throws, and
// numeric::Cancelled, leaving no file behind.
Cached<DefaultSpace> default_space(const DefaultsOptions& options = {});

// Every tool to draw: the study's 15 stimuli with their bootstrap regions, then every other catalog
// pairing placed from its descriptors (space::space_tools).
space::SpaceTools default_space_tools(const DefaultSpace& space);

}  // namespace nibrig::model::design
