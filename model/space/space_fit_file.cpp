#include "model/space/space_fit_file.hpp"

#include <chrono>

#include "model/space/fit_diagnostic.hpp"
#include "model/space/model_choice.hpp"

namespace nibrig::model::space {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

numeric::Progress step(const StepProgress& progress, std::string name) {
  if (!progress) return {};
  return [progress, name = std::move(name)](std::size_t done, std::size_t total) {
    progress(name, done, total);
  };
}

}  // namespace

FittedSpace fit_space_file(const SpaceInputs& in, const std::filesystem::path& judgments,
                           const std::filesystem::path& descriptors,
                           const SpaceFitSettings& settings, const StepProgress& progress) {
  FitOptions options;
  options.starts = settings.starts;
  options.seed = settings.seed;
  options.threads = settings.threads;
  options.stop = settings.stop;
  const auto start = std::chrono::steady_clock::now();
  FittedSpace out;
  SpaceProblem problem = in.problem;
  problem.model.family = settings.model;
  if (settings.choose_model) {
    ModelChoiceOptions choice_options;
    choice_options.candidates = settings.candidates;
    choice_options.cross_validation.folds = settings.folds;
    choice_options.cross_validation.seed = settings.seed;
    choice_options.cross_validation.fit = options;
    choice_options.cross_validation.fit.starts = settings.choice_starts;
    ModelChoice choice = choose_model(problem, choice_options, step(progress, kChoiceStep));
    problem.model.family = choice.chosen;
    out.file.model_reason = std::move(choice.reason);
    out.file.model_scores = std::move(choice.scores);
  } else {
    out.file.model_reason = settings.model == kPaperModel ? "the paper's model (the default), not chosen"
                                                          : "given, not chosen by cross-validation";
  }
  out.fit = fit_space(problem, options, step(progress, kFitStep));
  // Before anything uses its scale: a face shows these beside the fit.
  for (auto& w : diagnose_fit(problem, out.fit).warnings()) out.warnings.push_back(std::move(w));
  SpaceFile& file = out.file;
  file.seconds = seconds_since(start);
  file.stimuli = in.judgments.stimuli;
  file.coordinates = out.fit.coordinates;
  file.model = out.fit.model;
  file.lambda = in.problem.lambda;
  file.objective = out.fit.objective;
  file.negative_log_likelihood = out.fit.negative_log_likelihood;
  file.start_objectives = out.fit.start_objectives;
  file.triplets = in.judgments.triplets.size();
  file.responses = io::response_count(in.judgments);
  file.judgments = judgments.string();
  if (in.descriptors) {
    file.descriptor_names = in.descriptors->names;
    file.descriptors = in.descriptors->values;
    file.descriptor_source = descriptors.string();
    // A map from d descriptors (and a constant) to each axis needs more stimuli than unknowns.
    if (file.stimuli.size() > file.descriptor_names.size() + 1)
      file.descriptor_map =
          fit_descriptor_map(out.fit.coordinates, file.descriptors, file.descriptor_names);
    else
      out.warnings.push_back(
          std::to_string(file.stimuli.size()) + " stimuli are too few to learn a map from " +
          std::to_string(file.descriptor_names.size()) +
          " descriptors; no tool can be placed from descriptors with this space");
  }
  if (settings.bootstrap > 0) {
    // Each refit starts from the fitted space and model.
    SpaceProblem fitted_problem = problem;
    fitted_problem.model = out.fit.model;
    BootstrapOptions b;
    b.resamples = settings.bootstrap;
    b.seed = settings.seed;
    b.threads = settings.threads;
    b.stop = settings.stop;
    const auto b_start = std::chrono::steady_clock::now();
    const BootstrapResult regions =
        bootstrap_space(fitted_problem, out.fit.coordinates, b, step(progress, kBootstrapStep));
    file.regions = regions.regions;
    file.region_levels = regions.levels;
    file.bootstrap_resamples = settings.bootstrap;
    out.bootstrap_seconds = seconds_since(b_start);
    out.mean_region_sd = mean_per_axis_sd(regions);
  }
  return out;
}

}  // namespace nibrig::model::space
