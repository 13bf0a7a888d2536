#include "model/space/model_choice.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "model/space/dimension_scan.hpp"

namespace nibrig::model::space {

ModelChoice choose_model(const SpaceProblem& problem, const ModelChoiceOptions& options,
                         const numeric::Progress& progress) {
  if (options.candidates.empty())
    throw std::invalid_argument("a choice of model needs at least one candidate");
  DimensionScanOptions scan;
  scan.dims = {problem.dims};
  scan.lambdas = {problem.lambda};
  scan.models = {kPaperModel};
  for (const ModelFamily& f : options.candidates)
    if (std::find(scan.models.begin(), scan.models.end(), f) == scan.models.end())
      scan.models.push_back(f);
  scan.cross_validation = options.cross_validation;
  const Eigen::MatrixXd descriptors = problem.descriptors;
  const std::vector<DimensionScanPoint> points = scan_dimensions(
      problem, [&descriptors](std::size_t) { return descriptors; }, scan, progress);

  ModelChoice choice;
  std::size_t best = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const DimensionScanPoint& p = points[i];
    choice.scores.push_back({family_name(p.model), p.log_loss, p.majority_agreement,
                             p.individual_agreement, p.mean_error});
    // Strictly lower: on a tie the earlier candidate (the paper's first) stays.
    if (p.log_loss < points[best].log_loss) best = i;
  }
  choice.chosen = points[best].model;
  const ModelScore& chosen = choice.scores[best];
  const ModelScore& paper = choice.scores.front();
  char text[320];
  std::snprintf(text, sizeof text,
                "%d-fold cross-validation of %zu models on %zu triplets: the lowest held-out log "
                "loss, %.4f nats "
                "per answer (the paper's probit %.4f); majority agreement %.3f (probit %.3f)",
                options.cross_validation.folds, points.size(), problem.triplets.size(),
                chosen.log_loss, paper.log_loss, chosen.majority_agreement,
                paper.majority_agreement);
  choice.reason = text;
  return choice;
}

const ModelScore* score_of(const std::vector<ModelScore>& scores, const ModelFamily& family) {
  const std::string name = family_name(family);
  for (const ModelScore& s : scores)
    if (s.family == name) return &s;
  return nullptr;
}

}  // namespace nibrig::model::space
