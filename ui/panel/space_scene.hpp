// From a fitted space and the catalog to what the space view draws: the judged stimuli at their
// fitted places with their bootstrap regions, and every other catalog pairing placed from its
// descriptors with the map's prediction region (Fig. 15), each with its kind, μ and descriptors.
#pragma once

#include <filesystem>

#include "model/io/catalog_file.hpp"
#include "model/space/space_file.hpp"
#include "ui/panel/space_view.hpp"

namespace nibrig::ui::panel {

// Throws std::invalid_argument naming a stimulus whose name is not "tool/surface".
SpaceScene scene_of(const model::space::SpaceFile& space, const model::io::Catalog& catalog,
                    const std::filesystem::path& catalog_file, const std::string& title);

}  // namespace nibrig::ui::panel
