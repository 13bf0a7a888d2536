#include "ui/panel/study_plan_preview.hpp"

#include <algorithm>
#include <cstdio>
#include <system_error>

#include "model/space/simulated_observer.hpp"
#include "model/space/trial_plan.hpp"
#include "model/study/stimulus_list.hpp"
#include "model/study/study_results.hpp"
#include "model/study/trial_sequence.hpp"
#include "rt/stroke_source.hpp"
#include "ui/panel/widgets.hpp"

namespace nibrig::ui::panel {

namespace study = model::study;

namespace {

// A trial is a triplet: the reference, A and B, each felt at least once before an answer counts.
constexpr double kPlanPreviewStimuliPerTrial = 3.0;

// The mean time to an answer over every answered trial of the study in `folder` and how many there
// were; {0, 0} when there is no study or no answer yet, or it cannot be read (Start says why).
std::pair<double, std::size_t> plan_preview_measured_trial(const std::filesystem::path& folder) {
  try {
    const study::StudyData data = study::read_study(folder);
    double sum = 0.0;
    std::size_t n = 0;
    for (const auto& p : data.participants)
      for (const auto& r : p.responses) sum += r.response_s, ++n;
    return {n ? sum / static_cast<double>(n) : 0.0, n};
  } catch (const std::exception&) {
    return {0.0, 0};
  }
}

}  // namespace

study::StudyDefinition definition_from_list(const PlanRequest& r) {
  study::StudyDefinition d;
  d.stimuli = study::read_stimulus_list(r.stimuli);
  d.plan = r.plan;
  d.mode = r.mode;
  d.trials = r.trials;
  d.practice = r.practice;
  d.break_every = r.break_every;
  study::validate(d);
  return d;
}

PlanPreview preview_plan(const PlanRequest& r) {
  PlanPreview p;
  std::error_code ec;
  const std::filesystem::path study_file = r.study / study::kStudyFile;
  const bool study_exists = !r.study.empty() && std::filesystem::exists(study_file, ec);
  study::StudyDefinition d;
  try {
    if (!r.stimuli.empty()) {
      d = definition_from_list(r);
      if (study_exists)
        if (const auto difference = study::study_difference(study::read_study_file(study_file), d)) {
          p.problem = r.study.string() + " holds another study: " + *difference;
          return p;
        }
    } else if (study_exists) {
      d = study::read_study_file(study_file);
      p.from_folder = true;
    } else {
      p.problem = "no stimulus list yet: the plan is worked out from it";
      return p;
    }
    p.stimuli = d.stimuli.size();
    p.practice = std::min(d.practice, model::space::triplet_count(d.stimuli.size()));
    // As `nibrig experiment run` says them before a study starts (seed 1 where it has none).
    p.at_most = study::TrialSequence(d, 1).expected_at_most();
    p.estimate = study::estimate_trials(d, study::estimate_space(d.dims, d.stimuli.size()), study::kEstimateRuns, 1);
  } catch (const std::exception& e) {
    p.problem = e.what();
    return p;
  }
  const auto [measured_s, answers] = study_exists ? plan_preview_measured_trial(r.study) : std::pair<double, std::size_t>{};
  if (answers > 0) {
    p.seconds_per_trial = measured_s;
    p.answers_measured = answers;
  } else {
    // The actuator plays the study's sweep and the turntable runs the same one (TurntablePresenter).
    p.seconds_per_trial = kPlanPreviewStimuliPerTrial * rt::SweepStroke::kPaperPeriod;
  }
  return p;
}

std::vector<std::string> plan_lines(const PlanPreview& p) {
  if (!p.problem.empty()) return {"plan: " + p.problem};
  char size[256];
  const double main = std::max(0.0, p.estimate.mean - static_cast<double>(p.practice));
  std::snprintf(size, sizeof size,
                "plan%s: %zu stimuli, %zu practice + about %.0f main trials (%zu-%zu with practice over %zu "
                "simulated participants), at most %zu",
                p.from_folder ? " (the study folder's)" : "", p.stimuli, p.practice, main, p.estimate.least,
                p.estimate.most, p.estimate.runs, p.at_most);
  char time[256];
  if (p.answers_measured > 0)
    std::snprintf(time, sizeof time,
                  "expected duration: about %s (%.0f trials x %.1f s, the mean time to an answer over the "
                  "%zu trials answered in this study), rests besides",
                  duration_words(p.expected_s()).c_str(), p.estimate.mean, p.seconds_per_trial,
                  p.answers_measured);
  else
    std::snprintf(time, sizeof time,
                  "expected duration: at least %s (%.0f trials x %.0f s: each stimulus felt once through "
                  "the %.0f s sweep); measured once this study has answers",
                  duration_words(p.expected_s()).c_str(), p.estimate.mean, p.seconds_per_trial,
                  rt::SweepStroke::kPaperPeriod);
  return {size, time};
}

}  // namespace nibrig::ui::panel
