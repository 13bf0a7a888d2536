// The dimensionality and λ study of Fig. 8: for each number of dimensions, each weight of the
// descriptor correlation and each judgment model, the cross-validated error of predicting held-out
// triplet probabilities.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "model/space/cross_validation.hpp"

namespace nibrig::model::space {

struct DimensionScanOptions {
  std::vector<std::size_t> dims{1, 2, 3, 4};
  std::vector<double> lambdas{0.0};
  std::vector<ModelFamily> models{kPaperModel};
  CrossValidationOptions cross_validation;  // the same folds for every point
};

struct DimensionScanPoint {
  std::size_t dims = 0;
  double lambda = 0.0;
  ModelFamily model;
  double mean_error = 0.0, sd_error = 0.0;  // of the held-out mean |Δp| across folds
  double majority_agreement = 0.0;          // pooled over the folds
  double individual_agreement = 0.0;
  double log_loss = 0.0;  // pooled, nats per held-out response
};

// `descriptors(D)` gives the stimuli × D table that the axes of a D-dimensional space are tied to;
// it is only called for λ > 0. Throws std::invalid_argument for an empty list, or λ > 0 without a
// descriptor source; otherwise what cross_validate throws. `progress` counts fold fits over the
// whole scan (done 1..dims × lambdas × models × folds), the unit of work that takes seconds.
std::vector<DimensionScanPoint> scan_dimensions(
    const SpaceProblem& base, const std::function<Eigen::MatrixXd(std::size_t)>& descriptors,
    const DimensionScanOptions& options = {}, const numeric::Progress& progress = {});

}  // namespace nibrig::model::space
