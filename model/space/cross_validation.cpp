#include "model/space/cross_validation.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>

namespace nibrig::model::space {

std::vector<int> assign_folds(std::size_t triplets, int folds, unsigned seed) {
  if (folds < 2) throw std::invalid_argument("cross-validation needs at least 2 folds");
  if (static_cast<std::size_t>(folds) > triplets)
    throw std::invalid_argument(std::to_string(folds) + " folds for only " +
                                std::to_string(triplets) + " triplets");
  std::vector<std::size_t> order(triplets);
  std::iota(order.begin(), order.end(), 0);
  std::mt19937_64 generator(seed);
  std::shuffle(order.begin(), order.end(), generator);
  std::vector<int> fold(triplets);
  for (std::size_t k = 0; k < order.size(); ++k)
    fold[order[k]] = static_cast<int>(k % static_cast<std::size_t>(folds));
  return fold;
}

CrossValidationResult cross_validate(const SpaceProblem& problem,
                                     const CrossValidationOptions& options,
                                     const numeric::Progress& progress) {
  validate(problem);
  const std::vector<int> fold = assign_folds(problem.triplets.size(), options.folds, options.seed);
  CrossValidationResult result;
  std::vector<double> all_predicted;
  std::vector<io::Triplet> all_held_out;
  for (int f = 0; f < options.folds; ++f) {
    SpaceProblem training = problem;
    training.triplets.clear();
    std::vector<io::Triplet> held_out;
    for (std::size_t t = 0; t < problem.triplets.size(); ++t)
      (fold[t] == f ? held_out : training.triplets).push_back(problem.triplets[t]);
    const FitResult fit = fit_space(training, options.fit);

    std::vector<bool> seen(problem.stimuli, false);
    for (const auto& t : training.triplets) seen[t.reference] = seen[t.a] = seen[t.b] = true;
    FoldScores scores;
    scores.training_triplets = training.triplets.size();
    for (const auto& t : held_out)
      if (!seen[t.reference] || !seen[t.a] || !seen[t.b]) ++scores.unseen_stimulus_triplets;
    const std::vector<double> predicted = predict_triplets(fit.coordinates, held_out, fit.model);
    scores.scores = score_predictions(predicted, held_out);
    result.folds.push_back(scores);
    all_predicted.insert(all_predicted.end(), predicted.begin(), predicted.end());
    all_held_out.insert(all_held_out.end(), held_out.begin(), held_out.end());
    if (progress)
      progress(static_cast<std::size_t>(f) + 1, static_cast<std::size_t>(options.folds));
  }
  result.pooled = score_predictions(all_predicted, all_held_out);
  double sum = 0.0, sum_sq = 0.0;
  for (const auto& f : result.folds) {
    sum += f.scores.mean_absolute_error;
    sum_sq += f.scores.mean_absolute_error * f.scores.mean_absolute_error;
  }
  const double n = static_cast<double>(result.folds.size());
  result.mean_fold_error = sum / n;
  result.sd_fold_error = std::sqrt(std::max(0.0, (sum_sq - sum * sum / n) / (n - 1.0)));
  return result;
}

}  // namespace nibrig::model::space
