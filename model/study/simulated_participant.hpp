// A participant who is a model: answers drawn from a perceptual space by the Thurstonian observer
// of model/space (P(left) = Φ(−s·d)), with lapses (a share of answers given at random, as
// attention slips), a response time that grows with how hard the triplet is, and a way of
// exploring (reference, A, reference, B, then more back and forth the harder it is). For tests, and
// for estimating a study's length before anyone comes in.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "model/space/simulated_observer.hpp"
#include "model/space/space_file.hpp"
#include "model/study/study_session.hpp"

namespace nibrig::model::study {

struct SimulatedParticipantOptions {
  double lapse_rate = 0.0;  // share of answers at random; 0: the model's observer exactly
  // Response time = non_decision_s + a log-normal time whose median is median_s on an obvious
  // triplet and (1 + slowdown) × median_s on a coin toss; the paper's participants explored freely
  // for several seconds per trial.
  double non_decision_s = 1.0;
  double median_s = 5.0;
  double slowdown = 1.0;
  double log_sd = 0.35;
};

// Throws std::invalid_argument for a lapse rate outside [0, 1], a negative time or spread.
void validate(const SimulatedParticipantOptions& options);

class SimulatedParticipant final : public Respondent {
 public:
  // truth: dims × the study's stimuli; model: how they judge (a space's, for its noises one per
  // study stimulus: judgment_model_for_stimuli). Each trial's answer, plays and time are drawn from
  // the seed and the trial's number. Throws as SimulatedObserver and validate.
  SimulatedParticipant(Eigen::MatrixXd truth, SimulatedParticipantOptions options,
                       std::uint64_t seed, space::JudgmentModel model = {});

  bool agree(const StudyTexts&) override { return true; }
  Answer answer(const TrialPrompt& prompt, const std::function<void(Role)>& play) override;
  void rest(std::size_t, std::size_t) override {}

  const space::SimulatedObserver& observer() const noexcept { return observer_; }

 private:
  space::SimulatedObserver observer_;
  SimulatedParticipantOptions options_;
  std::uint64_t seed_;
};

// Where a stimulus the space neither judged nor finds in the catalog lies (a design point, placed
// from its predicted descriptors by a caller that can predict); nullopt: it cannot say.
using PlaceOther = std::function<std::optional<Eigen::VectorXd>(const Stimulus&)>;

// The simulated participant's space for a study's stimuli: each stimulus the space judged at its
// coordinates, any other catalog pairing placed from its descriptors through the space's map
// (when it has one; `catalog_file` empty: the bundled catalog), anything else where `other` says.
// Throws std::invalid_argument naming the space file and the stimulus it cannot place.
Eigen::MatrixXd truth_for_stimuli(const space::SpaceFile& space,
                                  const std::filesystem::path& space_file,
                                  const std::vector<Stimulus>& stimuli,
                                  const std::filesystem::path& catalog_file,
                                  const PlaceOther& other = {});

// How the simulated participant judges a study's stimuli: the space's judgment model (link, scale,
// lapse), with each judged stimulus's noise where the family has noises and the space's typical
// noise for a stimulus it did not judge (as `space predict` treats one).
space::JudgmentModel judgment_model_for_stimuli(const space::SpaceFile& space,
                                                const std::vector<Stimulus>& stimuli);

// How many trials a study takes, from simulated participants judging `truth` by `model` with seeds
// seed, seed + 1, ...: what the runner says before a study starts (two-stage's stage 2 depends on
// how many triplets tie).
struct TrialEstimate {
  double mean = 0.0;
  std::size_t least = 0, most = 0;  // practice included
  std::size_t runs = 0;
};
TrialEstimate estimate_trials(const StudyDefinition& definition, const Eigen::MatrixXd& truth,
                              std::size_t runs, std::uint64_t seed, unsigned threads = 0,
                              const space::JudgmentModel& model = {});

// The estimate a face gives before a study starts: kEstimateRuns simulated participants; when no
// space of the stimuli is known, they answer from estimate_space: a random space of the usual
// spread (seeded 1), the same for every face that says it.
inline constexpr std::size_t kEstimateRuns = 5;
Eigen::MatrixXd estimate_space(std::size_t dims, std::size_t stimuli);

}  // namespace nibrig::model::study
