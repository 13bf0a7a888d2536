#include "model/design/grid_guided_search.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <stdexcept>

#include "model/numeric/cancellation.hpp"
#include "model/numeric/parallel_for.hpp"

namespace nibrig::model::design {

namespace {

// The node intervals of `nodes` whose closed span holds x, with a relative margin for a point the
// search computed a rounding away from a node.
std::vector<std::size_t> spans_at(const std::vector<double>& nodes, double x) {
  const double margin = 1e-9 * (nodes.back() - nodes.front());
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i + 1 < nodes.size(); ++i)
    if (x >= nodes[i] - margin && x <= nodes[i + 1] + margin) out.push_back(i);
  return out;
}

std::pair<double, double> grid_coordinates(const GridAxes& axes, const DesignPoint& point) {
  for (const auto& share : point.mix)
    if (share.fraction > 0 && share.material != axes.material_a &&
        share.material != axes.material_b)
      throw std::invalid_argument("guided search: design " + to_string(point) +
                                  " is not a mix of the grid's " + axes.material_a + " and " +
                                  axes.material_b);
  return {point.fraction_of(axes.material_b), point.tip_diameter_m};
}

}  // namespace

std::vector<std::size_t> grid_cells_at(const GridAxes& axes, double fraction, double tip_m) {
  std::vector<std::size_t> out;
  const std::size_t tip_cells = axes.tips_m.size() - 1;
  for (const std::size_t i : spans_at(axes.fractions, fraction))
    for (const std::size_t j : spans_at(axes.tips_m, tip_m)) out.push_back(i * tip_cells + j);
  return out;
}

GuidedSearch guide_by_fem(SearchResult on_grid, const PredictionSetup& setup,
                          const DesignResponseGrid& grid, const std::string& surface,
                          const space::DescriptorMap& map, const Evaluate& by_fem, unsigned threads,
                          std::stop_token stop) {
  if (on_grid.evaluated.empty()) throw std::invalid_argument("guided search: no candidates");
  const auto& axes = grid.axes;
  std::vector<std::set<std::size_t>> cells_of;
  for (const Candidate& c : on_grid.evaluated) {
    if (c.score)
      throw std::invalid_argument("guided search: a scored candidate's rule is not a distance");
    const auto [fraction, tip] = grid_coordinates(axes, c.point);
    const auto cells = grid_cells_at(axes, fraction, tip);
    cells_of.emplace_back(cells.begin(), cells.end());
  }
  const double best_on_grid = std::min_element(on_grid.evaluated.begin(), on_grid.evaluated.end(),
                                               [](const Candidate& a, const Candidate& b) {
                                                 return a.distance < b.distance;
                                               })
                                  ->distance;

  GuidedSearch out;
  std::set<std::size_t> measured;
  std::vector<std::size_t> contenders;
  // ε only grows, so the contenders only grow: this ends when every cell they lie in is measured.
  for (;;) {
    contenders.clear();
    std::set<std::size_t> wanted;
    for (std::size_t k = 0; k < on_grid.evaluated.size(); ++k)
      if (on_grid.evaluated[k].distance <= best_on_grid + 2 * out.grid_error) {
        contenders.push_back(k);
        for (const std::size_t cell : cells_of[k])
          if (!measured.contains(cell)) wanted.insert(cell);
      }
    if (wanted.empty()) break;
    std::vector<std::pair<double, double>> centres;
    const std::size_t tip_cells = axes.tips_m.size() - 1;
    for (const std::size_t cell : wanted) {
      const std::size_t i = cell / tip_cells, j = cell % tip_cells;
      centres.emplace_back(0.5 * (axes.fractions[i] + axes.fractions[i + 1]),
                           0.5 * (axes.tips_m[j] + axes.tips_m[j + 1]));
      measured.insert(cell);
    }
    const GridError error = measure_grid_error_at(
        setup, grid, centres, surface, map.descriptor_names.size(), &map, {}, stop, threads);
    out.fem_solves += centres.size();
    out.grid_error = std::max(out.grid_error, error.placement_distance);
    out.checks.insert(out.checks.end(), error.cells.begin(), error.cells.end());
  }

  std::vector<std::optional<Candidate>> solved(contenders.size());
  numeric::parallel_for(contenders.size(), threads, [&](std::size_t n) {
    if (stop.stop_requested()) return;
    solved[n] = by_fem(on_grid.evaluated[contenders[n]].point);
  });
  numeric::throw_if_cancelled(stop, "guided search");
  out.fem_solves += contenders.size();
  out.fem_solved.assign(on_grid.evaluated.size(), false);
  for (std::size_t n = 0; n < contenders.size(); ++n) {
    on_grid.evaluated[contenders[n]] = std::move(*solved[n]);
    out.fem_solved[contenders[n]] = true;
  }
  on_grid.ranked = ranking(on_grid.evaluated);
  out.result = std::move(on_grid);
  return out;
}

}  // namespace nibrig::model::design
