// `nibrig space synth|plan|merge`: the synthetic validation of Fig. 10 (and adaptive vs two-stage),
// and the paper's two-stage experiment as trial lists an experimenter runs and feeds back.
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>
#include <iostream>
#include <nlohmann/json.hpp>

#include "model/io/format_error.hpp"
#include "model/io/text_lines.hpp"
#include "model/io/triplets.hpp"
#include "model/space/synthetic_study.hpp"
#include "model/space/trial_plan.hpp"
#include "model/space/two_stage_lists.hpp"
#include "model/study/stimulus_list.hpp"
#include "ui/cli/elapsed.hpp"
#include "ui/cli/output.hpp"
#include "ui/cli/space_commands.hpp"
#include "ui/report/figures.hpp"

namespace nibrig::ui::cli {

namespace space = model::space;

namespace {

nlohmann::json summary_json(const space::Summary& s) { return {{"mean", s.mean}, {"sd", s.sd}}; }

void write_recovery_chart(const std::vector<space::DimensionRecovery>& rows,
                          const std::filesystem::path& png) {
  report::IntervalChart chart;
  chart.title = "Synthetic recovery (Fig. 10): mean #(177) sd over random truths";
  chart.value_label = "mean |p#dfit#u - p#dtrue#u| (%)";
  for (const auto& r : rows)
    chart.bars.push_back({std::to_string(r.dims) + "-D", 100 * r.probability_error.mean,
                          100 * (r.probability_error.mean - r.probability_error.sd),
                          100 * (r.probability_error.mean + r.probability_error.sd),
                          "probability error"});
  report::write_interval_chart(chart, png);
}

}  // namespace

void run_space_synth(const SpaceSynthOptions& o, unsigned threads) {
  space::SyntheticStudyOptions study;
  study.trials = o.trials;
  study.dims = o.dims;
  study.stimuli = o.stimuli;
  study.seed = o.seed;
  study.threads = threads;
  study.fit_starts = o.starts;
  study.design = space::two_stage_for_budget(o.stimuli, 1966);
  if (o.stimuli == 15) study.design = space::TwoStageDesign{};  // the paper's exact sizes
  study.design.fit_data = o.all_judgments ? space::FitData::all_judgments : space::FitData::paper;
  const auto start = std::chrono::steady_clock::now();
  const auto rows = space::run_synthetic_study(study);
  const double seconds = seconds_since(start);
  std::cout << fmt::format(
      "Synthetic recovery (Fig. 10): {} random truths per dimension, {} stimuli, the paper's "
      "two-stage experiment, fitted on {}; {:.1f} s\n",
      o.trials, o.stimuli, o.all_judgments ? "every answer" : "the paper's selection", seconds);
  std::cout << " dims   trials  ties   coordinate error     probability error\n";
  nlohmann::json json = {
      {"trials", o.trials},
      {"stimuli", o.stimuli},
      {"fit_data", o.all_judgments ? "all_judgments" : "paper"},
      {"coordinate_error_definition",
       "RMS of the Procrustes-aligned error over stimuli / RMS distance of the truth from its "
       "centroid"},
      {"probability_error_definition", "mean over every triplet of |p_fit - p_truth|"},
      {"seconds", seconds},
      {"dimensions", nlohmann::json::array()}};
  for (const auto& r : rows) {
    std::cout << fmt::format("  {:>2}   {:>6.0f}  {:>4.0f}   {:5.1f} % ± {:4.1f} %    {:5.1f} % ± {:4.1f} %\n",
                             r.dims, r.trials.mean, r.ties.mean, 100 * r.coordinate_error.mean,
                             100 * r.coordinate_error.sd, 100 * r.probability_error.mean,
                             100 * r.probability_error.sd);
    json["dimensions"].push_back({{"dims", r.dims},
                                  {"coordinate_error", summary_json(r.coordinate_error)},
                                  {"probability_error", summary_json(r.probability_error)},
                                  {"trials_per_experiment", summary_json(r.trials)},
                                  {"ties", summary_json(r.ties)}});
  }
  if (o.compare) {
    space::DesignComparisonOptions c;
    c.trials = o.compare_trials;
    c.stimuli = o.stimuli;
    c.budgets = o.budgets;
    c.seed = o.seed;
    c.threads = threads;
    c.fit_starts = o.starts;
    c.two_stage_data = study.design.fit_data;
    const auto c_start = std::chrono::steady_clock::now();
    const auto budgets = space::compare_designs(c);
    std::cout << fmt::format(
        "Adaptive (expected information gain) vs two-stage, 2-D, {} truths; {:.1f} s\n"
        " budget   two-stage coord / prob        adaptive coord / prob\n",
        o.compare_trials, seconds_since(c_start));
    json["comparison"] = nlohmann::json::array();
    for (const auto& b : budgets) {
      std::cout << fmt::format("  {:>5}   {:5.1f} % / {:4.1f} % ± {:4.1f}    {:5.1f} % / {:4.1f} % ± {:4.1f}\n",
                               b.budget, 100 * b.two_stage_coordinates.mean,
                               100 * b.two_stage_probabilities.mean,
                               100 * b.two_stage_probabilities.sd, 100 * b.adaptive_coordinates.mean,
                               100 * b.adaptive_probabilities.mean,
                               100 * b.adaptive_probabilities.sd);
      json["comparison"].push_back(
          {{"budget", b.budget},
           {"two_stage_trials", summary_json(b.two_stage_trials)},
           {"two_stage_coordinate_error", summary_json(b.two_stage_coordinates)},
           {"two_stage_probability_error", summary_json(b.two_stage_probabilities)},
           {"adaptive_coordinate_error", summary_json(b.adaptive_coordinates)},
           {"adaptive_probability_error", summary_json(b.adaptive_probabilities)}});
    }
  }
  if (!o.output.empty()) {
    write_json_file(o.output, json);
    say_wrote(o.output);
  }
  if (!o.plots.empty()) {
    ensure_folder(o.plots);
    write_recovery_chart(rows, o.plots / "synthetic_recovery.png");
    say_wrote(o.plots / "synthetic_recovery.png");
  }
}

void run_space_plan(const SpacePlanOptions& o) {
  space::TrialList list;
  if (o.stage == 1) {
    list.stimuli = model::study::read_stimulus_names(o.input);
    list.trials = space::plan_all_triplets(list.stimuli.size(), o.repetitions ? o.repetitions : 2,
                                           o.seed, o.fraction);
  } else {
    space::TrialList answered = space::read_trial_csv(o.input, {}, space::kTwoStageLast);
    space::into_stage_one_stimuli(answered, o.input, space::stage_one_stimuli({o.input}, {answered}));
    const auto counts = space::merge_trials(answered.trials, answered.choices, 1);
    if (counts.empty())
      throw model::io::FormatError(o.input, "", "no answered stage-1 trial to find ties in");
    const auto ties = space::select_ties(counts);
    list.stimuli = answered.stimuli;
    list.trials = space::plan_stage_two(ties, o.repetitions ? o.repetitions : 10, o.seed,
                                        o.max_triplets);
    std::cout << fmt::format("{} of {} answered stage-1 triplets are ties; ", ties.size(),
                             counts.size());
  }
  ensure_folder(o.output.parent_path());
  space::write_trial_csv(o.output, list);
  std::cout << fmt::format("stage {}: {} trials over {} stimuli\n", o.stage, list.trials.size(),
                           list.stimuli.size());
  say_wrote(o.output);
}

void run_space_merge(const SpaceMergeOptions& o) {
  std::vector<space::TrialList> lists;
  for (const auto& file : o.lists) lists.push_back(space::read_trial_csv(file, {}, space::kTwoStageLast));
  const space::TwoStageStimuli two_stage = space::stage_one_stimuli(o.lists, lists);
  const std::vector<std::string>& stimuli = two_stage.names;
  std::vector<space::Trial> trials;
  std::vector<space::Choice> choices;
  for (std::size_t f = 0; f < lists.size(); ++f) {
    space::TrialList& list = lists[f];
    space::into_stage_one_stimuli(list, o.lists[f], two_stage);
    trials.insert(trials.end(), list.trials.begin(), list.trials.end());
    choices.insert(choices.end(), list.choices.begin(), list.choices.end());
  }
  model::io::TripletSet set;
  set.stimuli = stimuli;
  set.triplets = o.all_judgments
                     ? space::merge_trials(trials, choices)
                     : space::two_stage_counts(space::merge_trials(trials, choices, 1),
                                               space::merge_trials(trials, choices, 2));
  ensure_folder(o.output.parent_path());
  model::io::write_triplet_csv(o.output, set);
  std::cout << fmt::format("{} triplets with {} answers ({})\n", set.triplets.size(),
                           model::io::response_count(set),
                           o.all_judgments ? "every answer"
                                           : "the paper's selection: stage 2 and the stage-1 "
                                             "triplets that were not ties");
  say_wrote(o.output);
}

}  // namespace nibrig::ui::cli
