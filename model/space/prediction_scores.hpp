// How well predicted preference probabilities match judgments (Sec. 4.5 and 6.1): agreement with
// the majority answer of each triplet and with every individual answer, the mean error of the
// predicted probability, the z-test of the agreement against chance and the Pearson correlation of
// predicted and observed probabilities.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "model/io/triplets.hpp"
#include "model/space/judgment_model.hpp"
#include "model/space/statistics.hpp"

namespace nibrig::model::space {

struct PredictionScores {
  std::size_t triplets = 0;  // with at least one response
  std::size_t responses = 0;
  // Triplets whose answers were not tied; a prediction agrees when it favours the majority and
  // counts as half when it is exactly 0.5 (so that no tie-break can favour the first-listed
  // candidate: in the Salmon data the answer is always listed first).
  AgreementTest majority;
  AgreementTest individual;  // every response scored the same way
  // Mean over triplets of |p_predicted − count_a / (count_a + count_b)|: the paper's "error"
  // (17 % for its 5-fold validation, 19 % for new tools).
  double mean_absolute_error = 0.0;
  // Mean −log P(the answer given) per response, in nats (ln 2 = 0.693 for a coin): the proper
  // score a choice of model goes by, since it also weighs how sure each prediction was. A
  // prediction of exactly 0 or 1 is taken as 1e-12 from it, so one wrong certainty costs 27.6.
  double log_loss = 0.0;
  // Predicted against observed probability over the triplets; empty when either is constant (one
  // response per triplet, as in Salmon's data, leaves observed probabilities of 0 or 1 only, which
  // is still a valid correlation; a single triplet is not).
  std::optional<Correlation> probability_correlation;
  // Why there is none, when there is none ("every observed probability is 1"), so a report can say
  // so instead of leaving the promised number out.
  std::string no_correlation_because;
};

// predicted[t] is P(a chosen) for triplets[t]. Throws std::invalid_argument when the lengths
// differ, a prediction is not a probability, or no triplet has a response.
PredictionScores score_predictions(const std::vector<double>& predicted,
                                   const std::vector<io::Triplet>& triplets);

// P(a chosen) of every triplet under a space (dims × stimuli).
std::vector<double> predict_triplets(const Eigen::MatrixXd& coordinates,
                                     const std::vector<io::Triplet>& triplets, const JudgmentModel& model);

}  // namespace nibrig::model::space
