#include "model/space/model_choice.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "model/space/dimension_sweep.hpp"

namespace nibrig::model::space {

ModelChoice choose_model(const SpaceProblem& problem, const ModelChoiceOptions& options,
                         const numeric::Progress& progress) {
  if (options.candidates.empty())
    throw std::invalid_argument("a choice of model needs at least one candidate");
  SweepOptions sweep;
  sweep.dims = {problem.dims};
  sweep.lambdas = {problem.lambda};
  sweep.models = {kPaperModel};
  for (const ModelFamily& f : options.candidates)
    if (std::find(sweep.models.begin(), sweep.models.end(), f) == sweep.models.end())
      sweep.models.push_back(f);
  sweep.cross_validation = options.cross_validation;
  const Eigen::MatrixXd descriptors = problem.descriptors;
  const std::vector<SweepPoint> points = sweep_dimensions(
      problem, [&descriptors](std::size_t) { return descriptors; }, sweep, progress);

  ModelChoice choice;
  std::size_t best = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const SweepPoint& p = points[i];
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
