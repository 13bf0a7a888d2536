#include "model/space/synthetic_study.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "model/numeric/parallel_for.hpp"
#include "model/space/fit.hpp"
#include "model/space/procrustes.hpp"

namespace nibrig::model::space {
namespace {

// The paper's trial split (Sec. 4.3): 683 triplets × 2 in stage 1, 60 × 10 in stage 2.
constexpr double kStageOneShare = 1366.0 / 1966.0;

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// A seed for one job that depends only on the study seed and the job's identity, never on which
// thread runs it or in what order.
std::uint64_t job_seed(std::uint64_t seed, std::uint64_t a, std::uint64_t b) {
  return splitmix64(splitmix64(splitmix64(seed) ^ a) ^ (b * 0x9E3779B97F4A7C15ull));
}

Eigen::MatrixXd fit_counts(const std::vector<io::Triplet>& counts, std::size_t dims,
                           std::size_t stimuli, int starts, std::uint64_t seed) {
  SpaceProblem problem;
  problem.stimuli = stimuli;
  problem.dims = dims;
  problem.triplets = counts;
  FitOptions options;
  options.starts = starts;
  options.threads = 1;  // the study runs its trials in parallel instead
  options.seed = static_cast<unsigned>(seed);
  return fit_space(problem, options).coordinates;
}

void check_space_size(std::size_t dims, std::size_t stimuli) {
  if (dims < 1) throw std::invalid_argument("synthetic study: a dimensionality must be >= 1");
  if (stimuli < dims + 1 || stimuli < 3)
    throw std::invalid_argument("synthetic study: " + std::to_string(stimuli) +
                                " stimuli cannot span a " + std::to_string(dims) + "-D space");
}

}  // namespace

RecoveryError recovery_error(const Eigen::MatrixXd& fitted, const Eigen::MatrixXd& truth,
                             const JudgmentModel& model) {
  if (fitted.rows() != truth.rows() || fitted.cols() != truth.cols())
    throw std::invalid_argument("recovery_error: the fit and the truth differ in shape");
  const Eigen::MatrixXd aligned = procrustes_align(fitted, truth);
  const double error = std::sqrt((aligned - truth).colwise().squaredNorm().mean());
  const double spread =
      std::sqrt((truth.colwise() - truth.rowwise().mean()).colwise().squaredNorm().mean());
  RecoveryError result;
  result.coordinates = error / spread;
  const auto n = static_cast<std::size_t>(truth.cols());
  double sum = 0.0;
  const std::vector<io::Triplet> all = all_triplets(n);
  for (const io::Triplet& t : all)
    sum += std::abs(probability_first(model, fitted, t.reference, t.a, t.b) -
                    probability_first(model, truth, t.reference, t.a, t.b));
  result.probabilities = all.empty() ? 0.0 : sum / static_cast<double>(all.size());
  return result;
}

TwoStageDesign two_stage_for_budget(std::size_t stimuli, std::size_t budget) {
  const auto total = static_cast<double>(triplet_count(stimuli));
  if (total == 0) throw std::invalid_argument("a two-stage design needs at least 3 stimuli");
  TwoStageDesign design;
  const double stage_one = kStageOneShare * static_cast<double>(budget);
  design.stage_one_fraction =
      std::clamp(stage_one / (design.stage_one_repetitions * total), 1.0 / total, 1.0);
  design.stage_two_triplets = static_cast<std::size_t>(
      std::llround((static_cast<double>(budget) - stage_one) / design.stage_two_repetitions));
  // 0 would mean "every tie"; a budget too small for one stage-two triplet asks for one.
  design.stage_two_triplets = std::max<std::size_t>(1, design.stage_two_triplets);
  return design;
}

SimulatedExperiment simulate_two_stage(const SimulatedObserver& observer,
                                       const TwoStageDesign& design, std::uint64_t seed) {
  const auto n = static_cast<std::size_t>(observer.truth().cols());
  std::mt19937_64 generator(seed);
  const std::vector<Trial> one =
      plan_all_triplets(n, design.stage_one_repetitions, generator(), design.stage_one_fraction);
  const std::vector<Choice> answers_one = observer.answer(one, generator);
  const std::vector<io::Triplet> counts_one = merge_trials(one, answers_one);
  const std::vector<io::Triplet> ties = select_ties(counts_one, design.ties);
  const std::vector<Trial> two =
      plan_stage_two(ties, design.stage_two_repetitions, generator(), design.stage_two_triplets);
  const std::vector<Choice> answers_two = observer.answer(two, generator);
  SimulatedExperiment experiment;
  if (design.fit_data == FitData::paper) {
    experiment.counts = two_stage_counts(counts_one, merge_trials(two, answers_two), design.ties);
  } else {
    std::vector<Trial> both = one;
    both.insert(both.end(), two.begin(), two.end());
    std::vector<Choice> answers = answers_one;
    answers.insert(answers.end(), answers_two.begin(), answers_two.end());
    experiment.counts = merge_trials(both, answers);
  }
  experiment.trials = one.size() + two.size();
  experiment.ties = ties.size();
  return experiment;
}

Summary summarize(const std::vector<double>& values) {
  Summary s;
  if (values.empty()) return s;
  for (double v : values) s.mean += v;
  s.mean /= static_cast<double>(values.size());
  if (values.size() > 1) {
    double sq = 0.0;
    for (double v : values) sq += (v - s.mean) * (v - s.mean);
    s.sd = std::sqrt(sq / static_cast<double>(values.size() - 1));
  }
  return s;
}

std::vector<DimensionRecovery> run_synthetic_study(const SyntheticStudyOptions& options) {
  if (options.trials < 1) throw std::invalid_argument("synthetic study: no trials");
  for (std::size_t d : options.dims) check_space_size(d, options.stimuli);
  struct Outcome {
    RecoveryError error;
    std::size_t trials = 0, ties = 0;
  };
  const std::size_t jobs = options.dims.size() * options.trials;
  std::vector<Outcome> outcomes(jobs);
  numeric::parallel_for(jobs, options.threads, [&](std::size_t job) {
    const std::size_t dims = options.dims[job / options.trials];
    const std::size_t trial = job % options.trials;
    std::mt19937_64 generator(job_seed(options.seed, dims, trial));
    const SimulatedObserver observer(
        random_space(dims, options.stimuli, generator, options.truth_difference));
    const SimulatedExperiment experiment =
        simulate_two_stage(observer, options.design, generator());
    const Eigen::MatrixXd fit =
        fit_counts(experiment.counts, dims, options.stimuli, options.fit_starts, generator());
    outcomes[job] = {recovery_error(fit, observer.truth()), experiment.trials, experiment.ties};
  });

  std::vector<DimensionRecovery> results;
  for (std::size_t k = 0; k < options.dims.size(); ++k) {
    DimensionRecovery r;
    r.dims = options.dims[k];
    std::vector<double> coordinates, probabilities, trials, ties;
    for (std::size_t t = 0; t < options.trials; ++t) {
      const Outcome& o = outcomes[k * options.trials + t];
      r.per_trial.push_back(o.error);
      coordinates.push_back(o.error.coordinates);
      probabilities.push_back(o.error.probabilities);
      trials.push_back(static_cast<double>(o.trials));
      ties.push_back(static_cast<double>(o.ties));
    }
    r.coordinate_error = summarize(coordinates);
    r.probability_error = summarize(probabilities);
    r.trials = summarize(trials);
    r.ties = summarize(ties);
    results.push_back(std::move(r));
  }
  return results;
}

std::vector<BudgetComparison> compare_designs(const DesignComparisonOptions& options) {
  if (options.trials < 1) throw std::invalid_argument("design comparison: no trials");
  check_space_size(options.dims, options.stimuli);
  if (options.budgets.empty()) throw std::invalid_argument("design comparison: no budgets");
  for (std::size_t b : options.budgets)
    if (b < options.adaptive_initial)
      throw std::invalid_argument("design comparison: budget " + std::to_string(b) +
                                  " is below the adaptive start design (" +
                                  std::to_string(options.adaptive_initial) + " trials)");
  std::vector<std::size_t> distinct = options.budgets;
  std::sort(distinct.begin(), distinct.end());
  if (std::unique(distinct.begin(), distinct.end()) != distinct.end())
    throw std::invalid_argument("design comparison: a budget is listed twice");
  const std::size_t budgets = options.budgets.size();
  // Per trial and budget: two-stage trials used, then the four errors.
  struct Outcome {
    double trials = 0;
    RecoveryError two_stage, adaptive;
  };
  std::vector<Outcome> outcomes(options.trials * budgets);
  numeric::parallel_for(options.trials, options.threads, [&](std::size_t trial) {
    std::mt19937_64 generator(job_seed(options.seed, options.dims, trial));
    const SimulatedObserver observer(
        random_space(options.dims, options.stimuli, generator, options.truth_difference));
    for (std::size_t b = 0; b < budgets; ++b) {
      TwoStageDesign design = two_stage_for_budget(options.stimuli, options.budgets[b]);
      design.fit_data = options.two_stage_data;
      const SimulatedExperiment experiment = simulate_two_stage(observer, design, generator());
      const Eigen::MatrixXd fit = fit_counts(experiment.counts, options.dims, options.stimuli,
                                             options.fit_starts, generator());
      outcomes[trial * budgets + b].trials = static_cast<double>(experiment.trials);
      outcomes[trial * budgets + b].two_stage = recovery_error(fit, observer.truth());
    }
    AdaptiveOptions adaptive;
    adaptive.initial_trials = options.adaptive_initial;
    adaptive.batch_size = options.adaptive_batch;
    adaptive.checkpoints = options.budgets;
    adaptive.ensemble = options.ensemble;
    adaptive.fit.starts = options.fit_starts;
    adaptive.fit.threads = 1;
    adaptive.fit.seed = static_cast<unsigned>(generator());
    const std::vector<AdaptiveCheckpoint> checkpoints =
        run_adaptive_study(observer, options.dims, adaptive, generator());
    for (const AdaptiveCheckpoint& c : checkpoints) {
      const auto b = static_cast<std::size_t>(
          std::find(options.budgets.begin(), options.budgets.end(), c.trials) -
          options.budgets.begin());
      outcomes[trial * budgets + b].adaptive = recovery_error(c.coordinates, observer.truth());
    }
  });

  std::vector<BudgetComparison> rows;
  for (std::size_t b = 0; b < budgets; ++b) {
    std::vector<double> used, tc, tp, ac, ap;
    for (std::size_t t = 0; t < options.trials; ++t) {
      const Outcome& o = outcomes[t * budgets + b];
      used.push_back(o.trials);
      tc.push_back(o.two_stage.coordinates);
      tp.push_back(o.two_stage.probabilities);
      ac.push_back(o.adaptive.coordinates);
      ap.push_back(o.adaptive.probabilities);
    }
    rows.push_back({options.budgets[b], summarize(used), summarize(tc), summarize(tp),
                    summarize(ac), summarize(ap)});
  }
  return rows;
}

}  // namespace nibrig::model::space
