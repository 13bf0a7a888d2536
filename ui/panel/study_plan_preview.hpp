// What a study will ask of a participant, shown in the Experiment view's form before Start so that
// the experimenter can still change it: the plan's size (practice, main trials: the trial sequence's
// own "at most" and the runner's estimate from simulated participants, as `nibrig experiment run`
// says it) and how long that takes. Reads the stimulus list and the study folder, and simulates
// participants, so the view computes it on a background job, only when the form's plan changes.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "model/study/simulated_participant.hpp"
#include "model/study/study_definition.hpp"

namespace nibrig::ui::panel {

// What in the Experiment view's form bears on the plan.
struct PlanRequest {
  std::filesystem::path study, stimuli;
  model::study::StudyMode mode = model::study::StudyMode::actuator;
  model::study::PlanKind plan = model::study::PlanKind::two_stage;
  std::size_t trials = 0, practice = 3, break_every = 100;
  bool operator==(const PlanRequest&) const = default;
};

// The study a list makes with the form's settings (what Start writes). Throws what
// read_stimulus_list and validate throw.
model::study::StudyDefinition definition_from_list(const PlanRequest& request);

struct PlanPreview {
  std::string problem;  // why there is no plan to show (one line); empty when there is one
  bool from_folder = false;  // the plan is the study folder's own (no list in the form)
  std::size_t stimuli = 0, practice = 0;
  std::size_t at_most = 0;  // TrialSequence::expected_at_most: practice included
  model::study::TrialEstimate estimate;  // practice included
  // Per trial: measured (the mean time to an answer over the study's answered trials), or, before
  // anyone answered, the least a trial takes (its three stimuli felt once, one study sweep each).
  double seconds_per_trial = 0.0;
  std::size_t answers_measured = 0;  // 0: seconds_per_trial is the least
  double expected_s() const { return estimate.mean * seconds_per_trial; }
};

// Never throws: what goes wrong is the preview's problem, naming the file.
PlanPreview preview_plan(const PlanRequest& request);

// The preview in words, a line each: the plan's size, its duration; or the problem.
std::vector<std::string> plan_lines(const PlanPreview& preview);

}  // namespace nibrig::ui::panel
