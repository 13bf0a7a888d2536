// A synthetic ground truth for testing experiment designs (Sec. 4.5, Fig. 10): a random perceptual
// space and an observer who answers "which candidate is closer to the reference?" exactly as the
// Thurstonian model of objective.hpp says a person would.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <random>
#include <vector>

#include "model/space/objective.hpp"
#include "model/space/trial_plan.hpp"

namespace nibrig::model::space {

// The RMS, over every triplet, of the distance difference d = ‖Q_a−Q_r‖ − ‖Q_b−Q_r‖.
double rms_distance_difference(const Eigen::MatrixXd& coordinates);

// 1.5 units: s·d = 1 at the RMS difference, so a typical triplet is answered 84 % / 16 % and the
// bulk of |s·d| lies below 2 (95 % if d were normal), where a judgment still carries information
// about d (the Fisher information of one judgment, s²φ²/(Φ(1−Φ)), has fallen to a fifth of its peak
// at |s·d| = 2). Much larger spaces make almost every triplet obvious (all 2-0 in stage 1, nothing
// learnt about the distances' size); much smaller ones make every triplet a coin toss.
inline constexpr double kDefaultTruthDifference = 1.5;

// A random space, dims × stimuli: independent standard normal coordinates (isotropic, so no axis is
// special), then scaled as a whole so that rms_distance_difference equals `rms_difference`. Scaling
// by this difference rather than by the coordinates' spread keeps every dimensionality equally
// informative: in more dimensions distances concentrate and their differences shrink.
// Throws std::invalid_argument for dims < 1, stimuli < 3 or rms_difference <= 0.
Eigen::MatrixXd random_space(std::size_t dims, std::size_t stimuli, std::mt19937_64& generator,
                             double rms_difference = kDefaultTruthDifference);

// A ground truth in which perception follows the physical descriptors (stimuli × descriptors):
// each descriptor standardised (mean 0, sd 1), one per axis, then scaled as a whole to the given
// RMS distance difference. What `nibrig demo` uses to simulate an observer of the catalog's tools
// when no human judgments are at hand. Throws std::invalid_argument for fewer than 3 stimuli, no
// descriptor, a constant or non-finite descriptor.
Eigen::MatrixXd space_from_descriptors(const Eigen::MatrixXd& descriptors,
                                       double rms_difference = kDefaultTruthDifference);

class SimulatedObserver {
 public:
  // Throws std::invalid_argument for a space with fewer than 3 stimuli, a non-positive scale or a
  // model with noises for another number of stimuli.
  explicit SimulatedObserver(Eigen::MatrixXd truth, double scale = kThurstoneScale);
  // An observer who judges by another model (a link, a lapse, noises per stimulus).
  SimulatedObserver(Eigen::MatrixXd truth, JudgmentModel model);

  const Eigen::MatrixXd& truth() const { return truth_; }
  double scale() const { return model_.scale; }
  const JudgmentModel& model() const { return model_; }

  // P(a judged closer to the reference than b): probability_first of the truth.
  double probability_first(std::size_t reference, std::size_t a, std::size_t b) const;

  // One judgment: true when a is chosen, with probability probability_first.
  bool chooses_first(std::size_t reference, std::size_t a, std::size_t b,
                     std::mt19937_64& generator) const;

  // Every trial answered (left or right), in order.
  std::vector<Choice> answer(const std::vector<Trial>& trials, std::mt19937_64& generator) const;

 private:
  Eigen::MatrixXd truth_;
  JudgmentModel model_;
};

}  // namespace nibrig::model::space
