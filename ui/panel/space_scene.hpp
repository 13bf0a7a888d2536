// From the tools of a space (model/space/space_tools.hpp: the judged stimuli with their bootstrap
// regions, every other catalog pairing placed through the descriptor map) to what the space view
// draws, and the panel's two ways to a space: a file, or the default computed once and cached.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "model/design/cached_default.hpp"
#include "model/space/descriptor_map.hpp"
#include "model/space/space_file.hpp"
#include "model/space/space_tools.hpp"
#include "ui/panel/space_view.hpp"

namespace nibrig::ui::panel {

SpaceScene scene_of(const model::space::SpaceTools& tools, std::size_t dims, const std::string& title);

struct LoadedSpace {
  model::space::SpaceFile file;  // the space itself, as "Save space as" writes it
  SpaceScene scene;
  std::optional<model::space::DescriptorMap> map;
  std::vector<std::string> warnings;  // a cache that could not be read or written, a fit's caveat
};

// A space and its tools placed with `catalog_file` (empty: the bundled catalog), titled `title`.
// Throws what the catalog reader throws, naming the file.
LoadedSpace loaded_space_of(model::space::SpaceFile space, const std::filesystem::path& catalog_file,
                            const std::string& title);
// A space file, its tools placed with `catalog_file` (empty: the bundled catalog). Throws what the
// readers throw, naming the file.
LoadedSpace load_space_file(const std::filesystem::path& file, const std::filesystem::path& catalog_file);
// The demo's space (SIMULATED observer), read from the user cache or computed there first.
LoadedSpace load_default_space(const model::design::DefaultsOptions& options);

}  // namespace nibrig::ui::panel
