// Fitting a perceptual space: L-BFGS (LBFGSpp) on the objective of objective.hpp from many random
// starts in parallel, keeping the best; the judgment model's lapse and noises, where its family has
// them, are fitted with the coordinates. One stimulus is pinned at the origin (translation);
// rotation is fixed by the correlation term, scale by the likelihood. Reports the spread of the
// optima.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "model/numeric/cancellation.hpp"
#include "model/numeric/progress_counter.hpp"
#include "model/space/objective.hpp"

namespace nibrig::model::space {

// The most starts a fit takes (the command line's --starts checks the same): each start is a whole
// optimisation, and a billion would exhaust memory before the first ends.
inline constexpr int kMostFitStarts = 10000;

struct FitOptions {
  int starts = 16;
  unsigned threads = 0;       // 0: one per core
  unsigned seed = 1;          // start k uses seed + k: results do not depend on the thread count
  std::size_t pinned = 0;     // the stimulus held at the origin
  double start_spread = 1.0;  // standard deviation of the random starting coordinates
  int max_iterations = 1000;
  // When not empty (dims × stimuli), start 0 begins here instead of at random, shifted so that the
  // pinned stimulus sits at the origin: a refit on resampled data starts at the reference space.
  Eigen::MatrixXd initial;
  // Without `initial`, start 0 begins at spectral_start() (the judgments' own MDS), the others at
  // random; off, every start is random (the benchmark's starts, as numpy's reference draws them).
  bool spectral_start = true;
  // When set, starts not yet begun are skipped and the fit throws numeric::Cancelled (a start
  // already running finishes first: one start takes a fraction of a second).
  std::stop_token stop;
};

struct FitResult {
  Eigen::MatrixXd coordinates;  // dims × stimuli
  JudgmentModel model;          // problem.model with the parts its family fits fitted
  double objective = 0.0;
  double negative_log_likelihood = 0.0;
  double correlation_penalty = 0.0;      // −Σ log|r_d| (without λ)
  std::vector<double> start_objectives;  // the optimum each start reached, ascending
  int best_start = 0;
  int iterations = 0;  // of the best start
  // of the objective with its gradient, in the best start (a restart's first point is not
  // evaluated again)
  int evaluations = 0;
};

// Throws what validate(problem) throws, and std::invalid_argument for starts outside
// 1..kMostFitStarts ("starts: ..."), a pinned
// stimulus out of range or an initial space of the wrong shape. `progress` is called as each start
// finishes (done 1..starts), from the worker threads but never two at once.
FitResult fit_space(const SpaceProblem& problem, const FitOptions& options = {},
                    const numeric::Progress& progress = {});

}  // namespace nibrig::model::space
