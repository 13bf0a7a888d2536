// Choosing the judgment model by what predicts unseen judgments best: k-fold cross-validation of
// every candidate family on the judgments given (the same folds for each), and the lowest held-out
// log loss chosen. Log loss rather than agreement: it is a proper score (only the true
// probabilities minimise it), and agreement moves in whole triplets, so candidates that order
// every triplet alike tie on it however well they say how sure to be. The paper's model is always
// scored, so a report can put the choice beside it.
#pragma once

#include <string>
#include <vector>

#include "model/space/cross_validation.hpp"
#include "model/space/judgment_model.hpp"

namespace nibrig::model::space {

struct ModelChoiceOptions {
  std::vector<ModelFamily> candidates = every_family();  // the paper's is added when missing
  CrossValidationOptions cross_validation;
};

struct ModelChoice {
  ModelFamily chosen;
  std::vector<ModelScore> scores;  // one per candidate, the paper's first
  std::string reason;              // for the space file: how it was chosen and by what margin
};

// The problem's dims, λ and descriptors are kept; its model's family is replaced by each
// candidate's. Throws what cross_validate throws, and std::invalid_argument for no candidates.
// `progress` counts fold fits (done 1..candidates × folds).
ModelChoice choose_model(const SpaceProblem& problem, const ModelChoiceOptions& options = {},
                         const numeric::Progress& progress = {});

// The score of `family` among `scores` (nullptr when it was not a candidate).
const ModelScore* score_of(const std::vector<ModelScore>& scores, const ModelFamily& family);

}  // namespace nibrig::model::space
