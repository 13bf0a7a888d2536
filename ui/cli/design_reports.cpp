#include "ui/cli/design_reports.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "model/io/catalog_file.hpp"
#include "ui/cli/space_figures.hpp"

namespace nibrig::ui::cli {

namespace design = model::design;

void write_search_plot(const model::space::SpaceFile& space, const std::string& target,
                       const std::vector<PlacedTool>& placed_targets,
                       const design::SearchResult& result, const std::vector<std::size_t>& ends,
                       const std::string& surface, const std::filesystem::path& png) {
  std::vector<PlacedTool> placed = placed_targets;
  for (std::size_t k = 0; k < result.evaluated.size(); ++k) {
    if (k == result.ranked.front()) continue;
    const auto& c = result.evaluated[k];
    const bool end = std::find(ends.begin(), ends.end(), k) != ends.end();
    placed.push_back({end ? design::label(c.point) : "", c.placement,
                      end ? "the designs searched between" : "candidates", end});
  }
  const auto& best = result.best();
  placed.push_back({"optimum " + design::label(best.point), best.placement, "optimum", true});
  write_space_plot(space, placed, fmt::format("Designs on {} nearest {}", surface, target), png);
}

}  // namespace nibrig::ui::cli
