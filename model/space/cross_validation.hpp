// k-fold cross-validation of a perceptual space (Sec. 4.5: "5-fold validation ... an average error
// of 17 %"): the triplets are shuffled into k folds; each fold is predicted by a space fitted to the
// other k − 1 and scored against its own judgments.
#pragma once

#include <vector>

#include "model/space/fit.hpp"
#include "model/space/prediction_scores.hpp"

namespace nibrig::model::space {

struct CrossValidationOptions {
  int folds = 5;
  unsigned seed = 1;  // of the shuffle into folds
  FitOptions fit;     // every fold's fit
};

struct FoldScores {
  std::size_t training_triplets = 0;
  // Held-out triplets naming a stimulus that no training triplet contains: the fit cannot place
  // that stimulus, so these predictions are guesses (still scored, and counted here).
  std::size_t unseen_stimulus_triplets = 0;
  PredictionScores scores;
};

struct CrossValidationResult {
  std::vector<FoldScores> folds;
  PredictionScores pooled;  // every held-out prediction scored together
  double mean_fold_error = 0.0, sd_fold_error = 0.0;  // of mean_absolute_error across folds
};

// Throws what fit_space throws, and std::invalid_argument for fewer than 2 folds or more folds than
// triplets. `progress` is called as each fold's fit finishes (done 1..folds).
CrossValidationResult cross_validate(const SpaceProblem& problem,
                                     const CrossValidationOptions& options = {},
                                     const numeric::Progress& progress = {});

// The fold of every triplet: a seeded shuffle dealt round-robin, so fold sizes differ by at most 1.
std::vector<int> assign_folds(std::size_t triplets, int folds, unsigned seed);

}  // namespace nibrig::model::space
