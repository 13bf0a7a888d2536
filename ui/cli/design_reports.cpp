#include "ui/cli/design_reports.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "model/forcing/descriptor_error.hpp"
#include "model/io/catalog_file.hpp"
#include "model/space/catalog_descriptors.hpp"
#include "ui/cli/space_figures.hpp"

namespace nibrig::ui::cli {

namespace design = model::design;

std::string describe_descriptors(const design::PredictedTool& tool) {
  std::string mu = fmt::format("mu {:.3f}", tool.mu);
  std::string vibration =
      fmt::format("weighted mean vibration {:.4g}", tool.vibration.weighted_mean);
  if (!tool.descriptor_errors.empty()) {
    const auto names = model::space::paper_descriptor_names(2);  // μ, log10 weighted mean
    const Eigen::MatrixXd c = tool.descriptor_errors.block(names);
    if (c(0, 0) > 0) mu += fmt::format(" ± {:.4f}", std::sqrt(c(0, 0)));
    vibration += fmt::format(" ± {:.1f} %", model::forcing::percent_off(std::sqrt(c(1, 1))));
  }
  return mu + ", " + vibration;
}

void write_search_plot(const model::space::SpaceFile& space, const std::string& target,
                       const model::space::Placement* placed_target,
                       const design::SearchResult& result, const std::vector<std::size_t>& ends,
                       const std::string& surface, const std::filesystem::path& png) {
  std::vector<PlacedTool> placed;
  if (placed_target != nullptr) placed.push_back({target, *placed_target, "target", true});
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
