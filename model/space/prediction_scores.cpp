#include "model/space/prediction_scores.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "model/space/objective.hpp"

namespace nibrig::model::space {
namespace {

// 1 when the prediction favours the side with more answers, ½ at exactly 0.5, 0 otherwise.
double agreement(double p_first, bool first_won) {
  if (p_first == 0.5) return 0.5;
  return (p_first > 0.5) == first_won ? 1.0 : 0.0;
}

std::string shortest(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}

}  // namespace

PredictionScores score_predictions(const std::vector<double>& predicted,
                                   const std::vector<io::Triplet>& triplets) {
  if (predicted.size() != triplets.size())
    throw std::invalid_argument(std::to_string(predicted.size()) + " predictions for " +
                                std::to_string(triplets.size()) + " triplets");
  PredictionScores s;
  double majority_agree = 0.0, majority_n = 0.0, individual_agree = 0.0, error_sum = 0.0, loss_sum = 0.0;
  std::vector<double> p_predicted, p_observed;
  for (std::size_t t = 0; t < triplets.size(); ++t) {
    const double p = predicted[t];
    if (!(p >= 0.0 && p <= 1.0))
      throw std::invalid_argument("prediction " + std::to_string(t) + " is not a probability: " +
                                  std::to_string(p));
    const io::Triplet& tr = triplets[t];
    const int n = tr.count_a + tr.count_b;
    if (n == 0) continue;
    ++s.triplets;
    s.responses += static_cast<std::size_t>(n);
    individual_agree += tr.count_a * agreement(p, true) + tr.count_b * agreement(p, false);
    if (tr.count_a != tr.count_b) {
      majority_agree += agreement(p, tr.count_a > tr.count_b);
      majority_n += 1.0;
    }
    const double sure = std::clamp(p, 1e-12, 1.0 - 1e-12);
    loss_sum -= tr.count_a * std::log(sure) + tr.count_b * std::log1p(-sure);
    const double observed = static_cast<double>(tr.count_a) / n;
    error_sum += std::abs(p - observed);
    p_predicted.push_back(p);
    p_observed.push_back(observed);
  }
  if (s.triplets == 0) throw std::invalid_argument("no triplet has a response to score against");
  if (majority_n > 0) s.majority = agreement_test(majority_agree, majority_n);
  s.individual = agreement_test(individual_agree, static_cast<double>(s.responses));
  s.mean_absolute_error = error_sum / static_cast<double>(s.triplets);
  s.log_loss = loss_sum / static_cast<double>(s.responses);
  const auto constant = [](const std::vector<double>& v) {
    return std::all_of(v.begin(), v.end(), [&](double x) { return x == v.front(); });
  };
  if (p_predicted.size() < 3)
    s.no_correlation_because =
        std::to_string(p_predicted.size()) + " answered triplets (a correlation needs 3)";
  else if (constant(p_observed))
    s.no_correlation_because = "every observed probability is " + shortest(p_observed.front()) +
                               " (the answers do not vary between triplets)";
  else if (constant(p_predicted))
    s.no_correlation_because = "every predicted probability is the same";
  else
    s.probability_correlation = pearson(p_predicted, p_observed);
  return s;
}

std::vector<double> predict_triplets(const Eigen::MatrixXd& coordinates,
                                     const std::vector<io::Triplet>& triplets, const JudgmentModel& model) {
  std::vector<double> p;
  p.reserve(triplets.size());
  for (const auto& t : triplets)
    p.push_back(probability_first(model, coordinates, t.reference, t.a, t.b));
  return p;
}

}  // namespace nibrig::model::space
