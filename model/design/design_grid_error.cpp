#include "model/design/design_grid_error.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <optional>
#include <stdexcept>

#include "model/design/design_search.hpp"
#include "model/modal/frequency_response.hpp"
#include "model/numeric/cancellation.hpp"
#include "model/numeric/parallel_for.hpp"
#include "model/space/catalog_descriptors.hpp"

namespace nibrig::model::design {

namespace {

Eigen::VectorXd descriptors(const PredictedTool& tool, std::size_t dims) {
  io::Catalog one;  // as place_predicted reads a prediction: through the catalog's descriptors
  one.tools.push_back(predicted_tool_entry(tool));
  one.pairings.push_back(predicted_pairing(tool, "the catalog's"));
  return space::descriptors_of_catalog(one, "prediction", dims).values.row(0).transpose();
}

struct DbError {
  double rms = 0.0, max = 0.0;
};

DbError db_error(const std::vector<double>& got, const std::vector<double>& want) {
  DbError e;
  for (std::size_t j = 0; j < want.size(); ++j) {
    const double db = 20.0 * std::log10(got[j] / want[j]);
    e.rms += db * db;
    e.max = std::max(e.max, std::abs(db));
  }
  e.rms = std::sqrt(e.rms / static_cast<double>(want.size()));
  return e;
}

}  // namespace

GridError measure_grid_error(const PredictionSetup& setup, const DesignResponseGrid& grid,
                             const std::string& surface, std::size_t dims,
                             const space::DescriptorMap* map, const numeric::Progress& progress,
                             std::stop_token stop, unsigned threads) {
  const auto& axes = grid.axes;
  std::vector<std::pair<double, double>> centres;
  for (std::size_t i = 0; i + 1 < axes.fractions.size(); ++i)
    for (std::size_t j = 0; j + 1 < axes.tips_m.size(); ++j)
      centres.emplace_back(0.5 * (axes.fractions[i] + axes.fractions[i + 1]),
                           0.5 * (axes.tips_m[j] + axes.tips_m[j + 1]));
  return measure_grid_error_at(setup, grid, centres, surface, dims, map, progress, stop, threads);
}

GridError measure_grid_error_at(const PredictionSetup& setup, const DesignResponseGrid& grid,
                                const std::vector<std::pair<double, double>>& points,
                                const std::string& surface, std::size_t dims,
                                const space::DescriptorMap* map,
                                const numeric::Progress& progress, std::stop_token stop,
                                unsigned threads) {
  GridError result;
  result.descriptor_names = space::paper_descriptor_names(dims);
  if (map != nullptr && map->descriptor_names != result.descriptor_names)
    throw std::invalid_argument("grid error: the map's descriptors are not those of a " +
                                std::to_string(dims) + "-D space");
  const auto& axes = grid.axes;
  std::vector<std::optional<GridErrorAt>> cells(points.size());
  numeric::ProgressCounter counter(progress, cells.size());
  numeric::parallel_for(cells.size(), threads, [&](std::size_t n) {
    if (stop.stop_requested()) return;
    GridErrorAt at;
    at.fraction = points[n].first;
    at.tip_m = points[n].second;
    const DesignPoint point = grid_point(axes, at.fraction, at.tip_m);
    try {
      const PredictedTool fast = predict_from_grid(setup, grid, at.fraction, at.tip_m, surface);
      const PredictedTool full = predict_tool(setup, point, surface);
      const DbError h = db_error(fast.response_magnitude, full.response_magnitude);
      at.response_rms_db = h.rms;
      at.response_max_db = h.max;
      std::vector<double> modal_h;
      for (const auto& v : modal::frequency_response(fast.modal, grid.frequencies_hz))
        modal_h.push_back(std::abs(v));
      const DbError m = db_error(modal_h, full.response_magnitude);
      at.modal_response_rms_db = m.rms;
      at.modal_response_max_db = m.max;
      at.first_mode_error = fast.modal.omega.front() / full.modal.omega.front() - 1.0;
      const Eigen::VectorXd d = descriptors(fast, dims) - descriptors(full, dims);
      at.descriptor_error.assign(d.data(), d.data() + d.size());
      if (map != nullptr) {
        const space::Placement p_fast = place_predicted(*map, fast);
        const space::Placement p_full = place_predicted(*map, full);
        at.placement_distance = (p_fast.mean - p_full.mean).norm();
        at.placement_sd =
            std::sqrt(p_full.covariance.trace() / static_cast<double>(p_full.mean.size()));
      }
    } catch (const std::exception& e) {
      throw std::runtime_error("grid error at " + to_string(point) + ": " +
                               e.what());
    }
    cells[n] = at;
    counter.finished();
  });
  numeric::throw_if_cancelled(stop, "grid error");
  result.descriptor_error.assign(dims, 0.0);
  for (auto& cell : cells) {
    if (!cell) continue;
    result.response_rms_db = std::max(result.response_rms_db, cell->response_rms_db);
    result.response_max_db = std::max(result.response_max_db, cell->response_max_db);
    result.modal_response_rms_db =
        std::max(result.modal_response_rms_db, cell->modal_response_rms_db);
    for (std::size_t k = 0; k < dims; ++k)
      result.descriptor_error[k] =
          std::max(result.descriptor_error[k], std::abs(cell->descriptor_error[k]));
    if (map != nullptr) {
      result.placement_distance = std::isnan(result.placement_distance)
                                      ? cell->placement_distance
                                      : std::max(result.placement_distance, cell->placement_distance);
      result.placement_sd = std::isnan(result.placement_sd)
                                ? cell->placement_sd
                                : std::min(result.placement_sd, cell->placement_sd);
    }
    result.cells.push_back(std::move(*cell));
  }
  if (setup.descriptor_errors != nullptr && !setup.descriptor_errors->empty()) {
    const Eigen::MatrixXd c = setup.descriptor_errors->block(result.descriptor_names);
    for (Eigen::Index k = 0; k < c.rows(); ++k) result.cross_validated_sd.push_back(std::sqrt(c(k, k)));
  }
  return result;
}

}  // namespace nibrig::model::design
