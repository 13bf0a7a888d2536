#include "model/space/fit_diagnostic.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "model/space/judgment_model.hpp"

namespace nibrig::model::space {

FitDiagnostic diagnose_fit(const SpaceProblem& problem, const FitResult& fit) {
  FitDiagnostic d;
  d.free_coordinates = problem.dims * (problem.stimuli > 0 ? problem.stimuli - 1 : 0);
  d.largest_coordinate = fit.coordinates.size() > 0 ? fit.coordinates.cwiseAbs().maxCoeff() : 0.0;
  JudgmentModel model = fit.model;
  model.lapse = 0.0;
  for (const io::Triplet& t : problem.triplets) {
    const int n = t.count_a + t.count_b;
    if (n <= 0) continue;
    ++d.judged_triplets;
    const double p = probability_first(model, fit.coordinates, t.reference, t.a, t.b);
    const double minority = std::min(p, 1.0 - p);
    if (!(minority >= kBeyondAnswersFactor / (n + 2.0))) ++d.beyond_answers;
  }
  return d;
}

std::vector<std::string> FitDiagnostic::warnings() const {
  std::vector<std::string> out;
  if (unidentified()) {
    std::ostringstream s;
    s << "the fit is not identified: " << judged_triplets << " judged triplets for " << free_coordinates
      << " free coordinates (dims x (stimuli - 1)); more triplets, or fewer dimensions, are needed";
    out.push_back(s.str());
  }
  if (separable()) {
    std::ostringstream s;
    s << "the space's scale is arbitrary: " << beyond_answers << " of " << judged_triplets
      << " judged triplets are predicted more surely than their answers can tell (the answers are "
      << "separable, so the coordinates stretched until the optimiser stopped; largest |coordinate| "
      << largest_coordinate << "); judge more triplets, fit fewer dimensions or a model with a lapse";
    out.push_back(s.str());
  }
  return out;
}

}  // namespace nibrig::model::space
