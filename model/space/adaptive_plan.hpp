// Adaptive experiment design, the alternative to the paper's two-stage plan (Sec. 4.2): after each
// batch of answers, fit the space, describe what is still uncertain by an ensemble of plausible
// spaces, and ask next the triplets whose answer is expected to teach the most (BALD: expected
// information gain, Houlsby et al. 2011).
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

#include "model/io/triplets.hpp"
#include "model/space/fit.hpp"
#include "model/space/objective.hpp"
#include "model/space/simulated_observer.hpp"

namespace nibrig::model::space {

// H(p) = −p ln p − (1−p) ln(1−p) in nats; 0 at p = 0 and 1.
double binary_entropy(double p);

// BALD for one triplet from the probabilities the ensemble's members give it:
// H(mean_s p_s) − mean_s H(p_s). It is large only where the outcome is uncertain (H(mean) near
// ln 2) AND the members disagree (each member is itself confident); an answer the model already
// expects to be a coin toss teaches nothing about the space.
double bald(const std::vector<double>& member_probabilities);

// BALD of every candidate (its reference, a, b; counts ignored) under the ensemble (each dims ×
// stimuli). Throws std::invalid_argument for an empty ensemble, members of different shapes or a
// candidate out of range.
std::vector<double> expected_information_gain(const std::vector<Eigen::MatrixXd>& ensemble,
                                              const std::vector<io::Triplet>& candidates,
                                              const JudgmentModel& model = {});

// Indices of the batch_size largest gains, largest first, each candidate at most once (greedy
// top-K: it ignores that two chosen triplets may ask about the same thing, which the next batch's
// refit corrects). Ties in gain go to the lower index. All candidates when there are fewer.
std::vector<std::size_t> select_batch(const std::vector<double>& gains, std::size_t batch_size);

// The ensemble is a Laplace approximation around the fitted coordinates: samples from
// N(mode, (F + I/prior_sd²)⁻¹), F the Fisher information of the triplet likelihood in the free
// coordinates (the pinned stimulus stays at its place). Why this rather than refits on bootstrap
// resamples: it costs one Cholesky factorisation of a (dims·(stimuli−1))² matrix instead of S
// multi-start fits per batch, and early on, with a handful of answers per stimulus, bootstrap
// refits land in different local optima and reflections that must be aligned before they can be
// compared. Its limit is that it only sees the uncertainty of the mode it was given. F (the
// expected Hessian, s²·n·φ²/(Φ(1−Φ)) per triplet times g gᵀ, g = ∂d/∂Q) is positive semi-definite
// everywhere, unlike the observed Hessian away from the optimum. Its null space has two parts.
// Rotations about the pinned stimulus change no distance, so F is exactly 0 along them; they are
// projected out of every sample (a linearised rotation of finite size would also stretch the
// space, a spurious disagreement). Anything else the data leave free (a stimulus in no triplet
// yet) is held by the prior. The correlation term is ignored: it only orients the space.
struct LaplaceOptions {
  int samples = 32;
  double prior_sd = 2.0;  // units of the space: weak next to what a few answers pin down
  std::size_t pinned = 0;
};

// Throws std::invalid_argument when mode is not dims × stimuli of the problem, samples < 1 or
// prior_sd <= 0 (and what validate(problem) throws).
std::vector<Eigen::MatrixXd> laplace_ensemble(const SpaceProblem& problem,
                                              const Eigen::MatrixXd& mode,
                                              const LaplaceOptions& options,
                                              std::mt19937_64& generator);

// One batch of the adaptive plan after a fit: the ensemble around `mode`, the batch_size
// candidates of highest gain (each once), sides alternating down the batch (so that each side
// leads half the time), stage `stage`. What run_adaptive_study and a study with people ask next.
std::vector<Trial> next_adaptive_batch(const SpaceProblem& problem, const Eigen::MatrixXd& mode,
                                       const std::vector<io::Triplet>& candidates,
                                       const LaplaceOptions& ensemble, std::size_t batch_size,
                                       int stage, std::mt19937_64& generator);

// The adaptive loop with a simulated observer: a random start design (initial_trials distinct
// triplets, once each), then fit → ensemble → the batch of highest gain (each once) → answers,
// until the largest checkpoint. The fit at each checkpoint (a number of trials) is reported.
struct AdaptiveOptions {
  std::size_t initial_trials = 100;
  std::size_t batch_size = 100;
  std::vector<std::size_t> checkpoints = {1000};
  LaplaceOptions ensemble;
  FitOptions fit;  // problem-independent settings; its seed is varied per refit
};

struct AdaptiveCheckpoint {
  std::size_t trials = 0;
  Eigen::MatrixXd coordinates;  // the fit to the first `trials` answers
  std::vector<io::Triplet> counts;
};

// Throws std::invalid_argument for a batch size of 0, no checkpoints, or initial_trials larger
// than the first checkpoint or the number of triplets.
std::vector<AdaptiveCheckpoint> run_adaptive_study(const SimulatedObserver& observer,
                                                   std::size_t dims, const AdaptiveOptions& options,
                                                   std::uint64_t seed);

}  // namespace nibrig::model::space
