#include "model/space/dimension_scan.hpp"

#include <algorithm>
#include <stdexcept>

namespace nibrig::model::space {

std::vector<DimensionScanPoint> scan_dimensions(
    const SpaceProblem& base, const std::function<Eigen::MatrixXd(std::size_t)>& descriptors,
    const DimensionScanOptions& options, const numeric::Progress& progress) {
  if (options.dims.empty() || options.lambdas.empty() || options.models.empty())
    throw std::invalid_argument("the scan needs at least one dimension, one λ and one model");
  std::vector<DimensionScanPoint> points;
  const std::size_t folds = static_cast<std::size_t>(std::max(0, options.cross_validation.folds));
  const std::size_t total =
      options.dims.size() * options.lambdas.size() * options.models.size() * folds;
  for (std::size_t dims : options.dims) {
    for (double lambda : options.lambdas) {
      for (const ModelFamily& model : options.models) {
        SpaceProblem problem = base;
        problem.dims = dims;
        problem.lambda = lambda;
        problem.descriptors.resize(0, 0);
        problem.model = JudgmentModel{};
        problem.model.scale = base.model.scale;
        problem.model.family = model;
        if (lambda > 0) {
          if (!descriptors)
            throw std::invalid_argument("λ > 0 ties the axes to descriptors, and none were given");
          problem.descriptors = descriptors(dims);
        }
        // Folds of this point continue the count of the points before it.
        const std::size_t before = points.size() * folds;
        numeric::Progress fold_progress;
        if (progress)
          fold_progress = [&](std::size_t done, std::size_t) { progress(before + done, total); };
        const CrossValidationResult cv =
            cross_validate(problem, options.cross_validation, fold_progress);
        DimensionScanPoint p;
        p.dims = dims;
        p.lambda = lambda;
        p.model = model;
        p.log_loss = cv.pooled.log_loss;
        p.mean_error = cv.mean_fold_error;
        p.sd_error = cv.sd_fold_error;
        p.majority_agreement = cv.pooled.majority.fraction;
        p.individual_agreement = cv.pooled.individual.fraction;
        points.push_back(p);
      }
    }
  }
  return points;
}

}  // namespace nibrig::model::space
