// The order in which one participant meets the trials of a study: practice first, then the
// study's plan (the paper's two stages, the adaptive batches, a listed plan, or the validation's
// pairs against its reference), each part planned when the one before is answered. A pure function
// of the study, the participant's seed and the answers so far: replaying a participant's logged
// answers gives the same trials in the same order, which is what resuming after a crash relies on.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include "model/space/fit.hpp"
#include "model/space/synthetic_study.hpp"
#include "model/space/trial_plan.hpp"
#include "model/study/study_definition.hpp"

namespace nibrig::model::study {

struct PlannedTrial {
  space::Trial trial;     // stage: 1 or 2 for two-stage, the batch (1 = the random start) for
                          // adaptive, as listed for a listed plan, 1 for validation
  bool practice = false;  // answered, never fitted
};

// The sizes a study's plan works with, settled from its budget (StudyDefinition::trials).
struct PlanSizes {
  space::TwoStageDesign two_stage;     // two-stage
  std::size_t main_trials_at_most = 0;  // of the main part
  std::size_t adaptive_initial = 0, adaptive_batch = 0;  // adaptive
};
PlanSizes plan_sizes(const StudyDefinition& definition);
// The highest stage a trial of this study can have (PlannedTrial::trial.stage): 2 for two-stage,
// the last batch an adaptive budget allows, the highest listed, 1 for validation.
int last_stage(const StudyDefinition& definition);

class TrialSequence {
 public:
  // Throws what validate(definition) throws. `threads` only speeds up the adaptive plan's refits
  // (the trials do not depend on it).
  TrialSequence(StudyDefinition definition, std::uint64_t seed, unsigned threads = 0);

  // The trial to present now; nullopt when the study is complete. Calling it again without an
  // answer gives the same trial.
  std::optional<PlannedTrial> next();
  // The answer to the trial next() gave. Throws std::logic_error when there is none and
  // std::invalid_argument for Choice::none.
  void record(space::Choice choice);

  std::size_t answered() const noexcept { return choices_.size(); }
  // Practice plus the main part at most (two-stage: stage 2 as large as its cap allows, until
  // stage 1 is answered and the ties are known).
  std::size_t expected_at_most() const noexcept;
  const std::vector<PlannedTrial>& trials() const noexcept { return answered_; }
  const std::vector<space::Choice>& choices() const noexcept { return choices_; }
  const StudyDefinition& definition() const noexcept { return definition_; }

 private:
  enum class Part { practice, main_first, main_next, done };
  void plan_next_part();
  std::vector<space::Trial> adaptive_batch();

  StudyDefinition definition_;
  PlanSizes sizes_;
  std::mt19937_64 generator_;
  Part part_ = Part::practice;
  int adaptive_round_ = 1;
  space::FitOptions adaptive_fit_;
  std::vector<PlannedTrial> queue_;  // the part being presented
  std::size_t position_ = 0;         // in queue_
  std::vector<PlannedTrial> answered_;
  std::vector<space::Choice> choices_;
  std::size_t stage_two_size_ = 0;   // once known
  bool stage_two_known_ = false;
};

}  // namespace nibrig::model::study
