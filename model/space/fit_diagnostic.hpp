// What a fitted space's judgments cannot tell: a diagnostic every face shows beside a fit (the CLI
// and Python as warnings, the panel where it shows a fit's warnings), since a small study's space
// can stretch to axes in the thousands without any error.
#pragma once

#include <string>
#include <vector>

#include "model/space/fit.hpp"
#include "model/space/objective.hpp"

namespace nibrig::model::space {

// A judged triplet's prediction is "beyond its answers" when the model gives its minority answer a
// probability this many times below 1/(n + 2), the least Laplace's rule lets n answers back.
// Measured (tests/model/space/fit_diagnostic_test.cpp): a separable study (6 stimuli in 2-D, each
// triplet answered once without error) stretched to |q| 138 with 98 % of its triplets beyond; the
// well-posed fit of Salmon's alien eggs (15,054 triplets, 1-D) has 11 % beyond, its obvious pairs
// of eggs far apart. The factor and separable()'s half lie between the two with room on both sides.
inline constexpr double kBeyondAnswersFactor = 1e-3;

struct FitDiagnostic {
  std::size_t judged_triplets = 0;    // triplets with at least one answer
  std::size_t free_coordinates = 0;   // dims × (stimuli − 1): one stimulus is pinned
  std::size_t beyond_answers = 0;     // judged triplets predicted beyond their answers
  double largest_coordinate = 0.0;    // max |coordinate|, in the space's units
  bool unidentified() const { return judged_triplets < free_coordinates; }
  // Most judged triplets beyond their answers: the likelihood had no maximum (the answers are
  // separable) and the coordinates stretched until the optimiser stopped; their scale is arbitrary.
  bool separable() const { return judged_triplets > 0 && 2 * beyond_answers > judged_triplets; }
  // One line per problem, for a face to show; empty when there is none.
  std::vector<std::string> warnings() const;
};

// The judgment model's predictions at the fit, under the fitted model's link without its lapse (a
// lapse bounds every prediction away from 0 and would hide the stretch).
FitDiagnostic diagnose_fit(const SpaceProblem& problem, const FitResult& fit);

}  // namespace nibrig::model::space
