// The objective of the perceptual space (Sec. 4, Eq. 1-6): the negative log-likelihood of the
// triplet counts under the Thurstonian model P(a closer to ref) = Φ(−s·d), d = ‖Q_a−Q_r‖ −
// ‖Q_b−Q_r‖, minus λ·Σ_d log|corr(Q^d, D^d)| tying axis d to descriptor d; with its analytic
// gradient.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "model/io/triplets.hpp"

namespace nibrig::model::space {

// s = 2/3 makes one unit of distance difference 75 % preference (Φ(2/3) = 0.748), the scale of the
// authors' released code; the paper's Eq. 2 is a garbled fast approximation of Φ (ARCHITECTURE.md, "Science notes").
inline constexpr double kThurstoneScale = 2.0 / 3.0;

struct SpaceProblem {
  std::size_t stimuli = 0;
  std::size_t dims = 0;
  std::vector<io::Triplet> triplets;
  // stimuli × dims, column d the descriptor axis d is tied to; empty when λ = 0.
  Eigen::MatrixXd descriptors;
  double lambda = 0.0;
  double scale = kThurstoneScale;
  // 0: none, the objective of Eq. 6 exactly. > 0: a Gaussian prior N(0, prior_sd²) on every
  // coordinate adds Σ q²/(2·prior_sd²). With few judgments some configuration may explain every
  // answer; the likelihood then has no maximum and a fit stretches without bound (seen with one
  // answer per triplet in the adaptive study). A prior far wider than the space leaves
  // well-determined fits unchanged.
  double prior_sd = 0.0;
};

// Throws std::invalid_argument naming the triplet or field: an index out of range, a reference
// equal to a candidate, a negative count, descriptors of the wrong shape or with a constant column
// (no correlation exists), λ < 0, a negative prior_sd, fewer stimuli than dims + 1.
void validate(const SpaceProblem& problem);

// Objective at coordinates Q (dims × stimuli, one column per stimulus); when `gradient` is given it
// receives ∂/∂Q (same shape). Where two stimuli coincide the distance's gradient is taken as 0 (a
// subgradient); a correlation is smoothed as log √(r² + 1e-12) so that it stays finite through 0.
double objective(const SpaceProblem& problem, const Eigen::MatrixXd& coordinates,
                 Eigen::MatrixXd* gradient);

// The two parts separately (for reports): −log P_exp and −log P_corr (without λ).
double negative_log_likelihood(const SpaceProblem& problem, const Eigen::MatrixXd& coordinates);
double correlation_penalty(const SpaceProblem& problem, const Eigen::MatrixXd& coordinates);

// P(a judged closer to the reference than b) under the model.
double probability_first(const Eigen::MatrixXd& coordinates, std::size_t reference, std::size_t a,
                         std::size_t b, double scale = kThurstoneScale);

}  // namespace nibrig::model::space
