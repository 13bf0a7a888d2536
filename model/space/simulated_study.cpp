#include "model/space/simulated_study.hpp"

#include <random>

#include "model/space/simulated_observer.hpp"

namespace nibrig::model::space {

std::vector<std::string> demo_study_stimuli() {
  const std::vector<std::string> tools{"cryon", "stab", "vero1", "vero4", "DM854"};
  const std::vector<std::string> surfaces{"office", "note", "stone"};
  std::vector<std::string> names;
  for (const auto& t : tools)
    for (const auto& s : surfaces) names.push_back(t + "/" + s);
  return names;
}

SimulatedStudy run_simulated_study(const io::Catalog& catalog,
                                   const std::filesystem::path& catalog_file,
                                   const SimulatedStudyOptions& o) {
  SimulatedStudy study;
  const std::vector<std::string>& stimuli = o.stimuli;
  study.descriptors = descriptors_for_stimuli(catalog, catalog_file, stimuli, o.dims);

  // The trial lists a real experiment would produce, answered by the simulated observer; one
  // generator answers both stages, in order, as the demo always has (its numbers depend on it).
  const SimulatedObserver observer(space_from_descriptors(study.descriptors.values));
  study.truth = observer.truth();
  std::mt19937_64 generator(o.observer_seed);
  study.stage_one = {stimuli,
                     plan_all_triplets(stimuli.size(), o.stage_one_repetitions,
                                       o.stage_one_plan_seed, o.stage_one_fraction),
                     {}};
  study.stage_one.choices = observer.answer(study.stage_one.trials, generator);
  const auto ties = select_ties(merge_trials(study.stage_one.trials, study.stage_one.choices));
  study.ties = ties.size();
  study.stage_two = {stimuli,
                     plan_stage_two(ties, o.stage_two_repetitions, o.stage_two_plan_seed,
                                    o.stage_two_triplets),
                     {}};
  study.stage_two.choices = observer.answer(study.stage_two.trials, generator);

  std::vector<Trial> trials = study.stage_one.trials;
  trials.insert(trials.end(), study.stage_two.trials.begin(), study.stage_two.trials.end());
  std::vector<Choice> choices = study.stage_one.choices;
  choices.insert(choices.end(), study.stage_two.choices.begin(), study.stage_two.choices.end());
  study.judgments.stimuli = stimuli;
  study.judgments.triplets = merge_trials(trials, choices);

  study.problem.stimuli = stimuli.size();
  study.problem.dims = o.dims;
  study.problem.triplets = study.judgments.triplets;
  study.problem.lambda = o.lambda;
  study.problem.descriptors = study.descriptors.values;

  numeric::throw_if_cancelled(o.stop, "simulated study");
  FitOptions fit_options;
  fit_options.threads = o.threads;
  fit_options.stop = o.stop;
  study.fit = fit_space(study.problem, fit_options,
                        numeric::step_progress(o.progress, "space fit starts",
                                               static_cast<std::size_t>(fit_options.starts)));
  BootstrapOptions b;
  b.resamples = o.bootstrap_resamples;
  b.threads = o.threads;
  b.stop = o.stop;
  study.bootstrap = bootstrap_space(
      study.problem, study.fit.coordinates, b,
      numeric::step_progress(o.progress, "bootstrap refits",
                             static_cast<std::size_t>(b.resamples)));

  SpaceFile& file = study.space;
  file.stimuli = stimuli;
  file.coordinates = study.fit.coordinates;
  file.model = study.fit.model;
  file.lambda = o.lambda;
  file.objective = study.fit.objective;
  file.negative_log_likelihood = study.fit.negative_log_likelihood;
  file.start_objectives = study.fit.start_objectives;
  file.triplets = study.judgments.triplets.size();
  file.responses = io::response_count(study.judgments);
  file.judgments = (o.judgments_file.empty() ? std::string("not written") : o.judgments_file) +
                   " (SIMULATED observer, not human judgments)";
  file.descriptor_names = study.descriptors.names;
  file.descriptors = study.descriptors.values;
  file.descriptor_source = catalog_file.string();
  file.descriptor_map =
      fit_descriptor_map(study.fit.coordinates, study.descriptors.values, study.descriptors.names);
  file.regions = study.bootstrap.regions;
  file.region_levels = study.bootstrap.levels;
  file.bootstrap_resamples = o.bootstrap_resamples;
  return study;
}

std::vector<DimensionScanPoint> scan_simulated_study(const SimulatedStudy& study,
                                                     const io::Catalog& catalog,
                                                     const std::filesystem::path& catalog_file,
                                                     const SimulatedStudyOptions& o) {
  DimensionScanOptions scan;
  scan.dims = {1, 2, 3};
  scan.lambdas = {0.0, o.lambda};
  scan.cross_validation.fit.starts = 4;
  scan.cross_validation.fit.threads = o.threads;
  scan.cross_validation.fit.stop = o.stop;
  const std::size_t folds = scan.dims.size() * scan.lambdas.size() *
                            static_cast<std::size_t>(scan.cross_validation.folds);
  return scan_dimensions(
      study.problem,
      [&](std::size_t d) {
        return descriptors_for_stimuli(catalog, catalog_file, o.stimuli, d).values;
      },
      scan, numeric::step_progress(o.progress, "cross-validation folds", folds));
}

}  // namespace nibrig::model::space
