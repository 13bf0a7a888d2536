// Simulated judgments for the space tests: every triplet of a known space judged a number of times
// by a Thurstonian observer, so that a fit, a cross-validation or a bootstrap can be checked
// against the truth.
#pragma once

#include <Eigen/Core>
#include <random>

#include "model/space/objective.hpp"

namespace nibrig::model::space::testing {

// Uniform in ±half_width per coordinate: ±2 units gives preferences of 75-95 % between typical
// triplets, the informative range of Φ(−2/3·d).
inline Eigen::MatrixXd random_truth(Eigen::Index dims, Eigen::Index stimuli, unsigned seed,
                                    double half_width = 2.0) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> spread(-half_width, half_width);
  Eigen::MatrixXd truth(dims, stimuli);
  for (Eigen::Index i = 0; i < truth.size(); ++i) truth.data()[i] = spread(generator);
  return truth;
}

// By the paper's observer unless another judgment model is given (a link, a lapse, noises).
inline SpaceProblem every_triplet_judged(const Eigen::MatrixXd& truth, int judgments, unsigned seed,
                                         const JudgmentModel& model = {}) {
  std::mt19937 generator(seed);
  SpaceProblem p;
  p.dims = static_cast<std::size_t>(truth.rows());
  p.stimuli = static_cast<std::size_t>(truth.cols());
  for (std::size_t r = 0; r < p.stimuli; ++r)
    for (std::size_t a = 0; a < p.stimuli; ++a)
      for (std::size_t b = a + 1; b < p.stimuli; ++b) {
        if (a == r || b == r) continue;
        std::binomial_distribution<int> observer(judgments,
                                                 probability_first(model, truth, r, a, b));
        io::Triplet t;
        t.reference = r, t.a = a, t.b = b;
        t.count_a = observer(generator);
        t.count_b = judgments - t.count_a;
        p.triplets.push_back(t);
      }
  return p;
}

// 60 random triplets of `stimuli` with counts 0-6 and a random descriptor per axis: a problem that
// exercises every term of the objective, for checks of its gradient.
inline SpaceProblem random_problem(std::size_t stimuli, std::size_t dims, double lambda,
                                   unsigned seed) {
  std::mt19937 generator(seed);
  std::uniform_int_distribution<std::size_t> pick(0, stimuli - 1);
  std::uniform_int_distribution<int> count(0, 6);
  SpaceProblem p;
  p.stimuli = stimuli;
  p.dims = dims;
  p.lambda = lambda;
  while (p.triplets.size() < 60) {
    io::Triplet t;
    t.reference = pick(generator), t.a = pick(generator), t.b = pick(generator);
    if (t.reference == t.a || t.reference == t.b || t.a == t.b) continue;
    t.count_a = count(generator), t.count_b = count(generator);
    p.triplets.push_back(t);
  }
  std::normal_distribution<double> normal;
  p.descriptors = Eigen::MatrixXd(stimuli, dims);
  for (Eigen::Index i = 0; i < p.descriptors.size(); ++i)
    p.descriptors.data()[i] = normal(generator);
  return p;
}

}  // namespace nibrig::model::space::testing
