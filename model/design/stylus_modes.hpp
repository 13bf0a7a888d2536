// The modes of the stylus every catalog tool is played through (by default the bundled printed
// stylus with a 2 mm tip): meshed and solved once (seconds; most of a minute under the sanitizers)
// and kept in the user cache under a key of the design's and the materials' bytes, so that each
// face or process that plays a catalog tool does not solve the same FEM again.
#pragma once

#include <filesystem>
#include <string>

#include "model/design/cached_default.hpp"
#include "model/modal/modal_model.hpp"

namespace nibrig::model::design {

// Bumped whenever the FEM or the file changes what a key's file holds.
inline constexpr int kStylusModesVersion = 1;

struct StylusModes {
  std::string design_name;
  modal::ModalModel modal;
};

// <cache>/stylus_modes-<key>.json when it is there and reads; else the design (empty: the bundled
// one) is meshed and solved with the bundled materials, and the modes written there atomically.
// Throws what reading the design or the materials throws, naming the file.
Cached<StylusModes> stylus_modes(const std::filesystem::path& design_file,
                                 const std::filesystem::path& cache_dir = {});

// Where stylus_modes keeps the modes of that design (there or not yet): its key is the design's and
// the materials' bytes. Throws what reading them throws.
std::filesystem::path stylus_modes_file(const std::filesystem::path& design_file,
                                        const std::filesystem::path& cache_dir = {});

}  // namespace nibrig::model::design
