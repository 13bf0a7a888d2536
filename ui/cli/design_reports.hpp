// What `nibrig predict`, `nibrig design` and the demo show of predicted designs: their descriptors
// in a line and the search's path in the space (Fig. 17). The prediction file and the search's
// JSON are model/design/prediction_file.hpp and design_search_file.hpp.
#pragma once

#include <filesystem>
#include <string>

#include "model/design/design_search.hpp"
#include "model/design/predicted_tool.hpp"
#include "model/io/catalog_file.hpp"
#include "model/measure/threshold_curve.hpp"
#include "model/space/space_file.hpp"
#include "ui/figures/predicted_text.hpp"
#include "ui/figures/space_scatter.hpp"

namespace nibrig::ui::cli {

using figures::describe_descriptors;

// The space's judged stimuli, the targets placed rather than judged, every candidate
// (the path; `ends` of them labelled, e.g. the two designs of a line search) and the optimum with
// its 68 % / 95 % ellipses.
void write_search_plot(const model::space::SpaceFile& space, const std::string& target,
                       const std::vector<figures::PlacedTool>& placed_targets,
                       const model::design::SearchResult& result,
                       const std::vector<std::size_t>& ends, const std::string& surface,
                       const std::filesystem::path& png);

}  // namespace nibrig::ui::cli
