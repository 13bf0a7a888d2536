// The objective of the perceptual space (Sec. 4, Eq. 1-6): the negative log-likelihood of the
// triplet counts under the judgment model (judgment_model.hpp; the paper's is P(a closer to ref) =
// Φ(−s·d), d = ‖Q_a−Q_r‖ − ‖Q_b−Q_r‖), minus λ·Σ_d log|corr(Q^d, D^d)| tying axis d to descriptor
// d, plus the priors; with its analytic gradient, in the coordinates and in the model's fitted parts.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "model/io/triplets.hpp"
#include "model/space/judgment_model.hpp"

namespace nibrig::model::space {

// The largest weight of the descriptor correlation (Eq. 6's λ) a problem may have.
inline constexpr double kMaxLambda = 1e4;

struct SpaceProblem {
  std::size_t stimuli = 0;
  std::size_t dims = 0;
  std::vector<io::Triplet> triplets;
  // stimuli × dims, column d the descriptor axis d is tied to; empty when λ = 0.
  Eigen::MatrixXd descriptors;
  double lambda = 0.0;
  // The link, the scale, and which parts a fit adds (family); its lapse and noises are where a fit
  // starts, and what objective(problem, Q) holds fixed.
  JudgmentModel model;
  // 0: none, the objective of Eq. 6 exactly. > 0: a Gaussian prior N(0, prior_sd²) on every
  // coordinate adds Σ q²/(2·prior_sd²). With few judgments some configuration may explain every
  // answer; the likelihood then has no maximum and a fit stretches without bound (seen with one
  // answer per triplet in the adaptive study). A prior far wider than the space leaves
  // well-determined fits unchanged.
  double prior_sd = 0.0;
};

// The problem as fitted: with kStudentCoordinatePriorSd as its coordinate prior when its link is
// Student-t and it has none.
SpaceProblem with_link_prior(SpaceProblem problem);

// Throws std::invalid_argument naming the triplet or field: an index out of range, a reference
// equal to a candidate, a negative count, descriptors of the wrong shape or with a constant column
// (no correlation exists), λ outside [0, kMaxLambda], a negative prior_sd, fewer stimuli than dims + 1.
void validate(const SpaceProblem& problem);

// Objective at coordinates Q (dims × stimuli, one column per stimulus); when `gradient` is given it
// receives ∂/∂Q (same shape). Where two stimuli coincide the distance's gradient is taken as 0 (a
// subgradient); a correlation is smoothed as log √(r² + 1e-12) so that it stays finite through 0.
double objective(const SpaceProblem& problem, const Eigen::MatrixXd& coordinates,
                 Eigen::MatrixXd* gradient);

// The objective at a model of problem.model's family, with its gradient in the parts the family
// fits: ∂/∂ε when it has a lapse, ∂/∂η per stimulus (the prior N(0, kNoisePriorSd²) included) when
// it has noises.
struct ModelGradient {
  double lapse = 0.0;
  Eigen::VectorXd log_noise;
};
double objective(const SpaceProblem& problem, const Eigen::MatrixXd& coordinates, const JudgmentModel& model,
                 Eigen::MatrixXd* gradient, ModelGradient* model_gradient);

// Which build of the likelihood's loops runs: the AVX2 one where the CPU has AVX2 (automatic, what
// the objectives above do), or one of the two by name, so that a test can compare their bits.
// LoopBuild::avx2 on a CPU without AVX2 throws std::invalid_argument.
enum class LoopBuild { automatic, portable, avx2 };
double objective(const SpaceProblem& problem, const Eigen::MatrixXd& coordinates,
                 const JudgmentModel& model, Eigen::MatrixXd* gradient,
                 ModelGradient* model_gradient, LoopBuild build);

// The two parts separately (for reports): −log P_exp (under problem.model) and −log P_corr
// (without λ).
double negative_log_likelihood(const SpaceProblem& problem, const Eigen::MatrixXd& coordinates);
double correlation_penalty(const SpaceProblem& problem, const Eigen::MatrixXd& coordinates);

}  // namespace nibrig::model::space
