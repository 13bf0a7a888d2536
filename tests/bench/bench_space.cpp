// Cost of fitting a perceptual space: the paper's study size (15 stimuli, every one of the 1365
// triplets, a simulated observer) in 2-D with 16 starts, 1000 bootstrap refits of it (Fig. 9), and
// the Lagunas et al. 2019 training split (100 materials) in 3-D. Targets: < 0.1 s,
// < 20 s, < 10 s on this 2-core machine.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <random>

#include "model/io/triplets.hpp"
#include "model/space/bootstrap.hpp"
#include "model/space/fit.hpp"
#include "model/space/space_fit_file.hpp"
#include "model/space/space_inputs.hpp"
#include "tests/support/test_paths.hpp"

namespace {

using namespace nibrig::model;

space::SpaceProblem paper_sized_study() {
  std::mt19937 generator(2018);
  std::uniform_real_distribution<double> spread(-2.0, 2.0);
  Eigen::MatrixXd truth(2, 15);
  for (Eigen::Index i = 0; i < truth.size(); ++i) truth.data()[i] = spread(generator);
  space::SpaceProblem p;
  p.dims = 2;
  p.stimuli = 15;
  for (std::size_t r = 0; r < 15; ++r)
    for (std::size_t a = 0; a < 15; ++a)
      for (std::size_t b = a + 1; b < 15; ++b) {
        if (a == r || b == r) continue;
        std::binomial_distribution<int> observer(
            2, space::probability_first(space::JudgmentModel{}, truth, r, a, b));
        io::Triplet t;
        t.reference = r, t.a = a, t.b = b;
        t.count_a = observer(generator);
        t.count_b = 2 - t.count_a;
        p.triplets.push_back(t);
      }
  return p;
}

void BM_FitPaperSizedStudy2D(benchmark::State& state) {
  const space::SpaceProblem study = paper_sized_study();
  space::FitOptions options;
  options.starts = 16;
  for (auto _ : state) {
    const auto fit = space::fit_space(study, options);
    benchmark::DoNotOptimize(fit.objective);
  }
  state.counters["triplets"] = static_cast<double>(study.triplets.size());
}

void BM_FitLagunas3D(benchmark::State& state) {
  const io::TripletSet set = io::read_lagunas_json(nibrig::test::shared_data() / "lagunas2019" /
                                                   "answers_processed_train.json");
  space::SpaceProblem p;
  p.dims = 3;
  p.stimuli = set.stimuli.size();
  p.triplets = set.triplets;
  space::FitOptions options;
  options.starts = 8;
  for (auto _ : state) {
    const auto fit = space::fit_space(p, options);
    benchmark::DoNotOptimize(fit.objective);
    state.counters["objective"] = fit.objective;
  }
  state.counters["triplets"] = static_cast<double>(p.triplets.size());
}

// The same fit as every face makes it (`nibrig space fit`, the panel, nibrig.space.fit): the fit
// with its diagnosis and the space file's statistics, the judgments read before the loop. What
// tests/bench/python_space_fit.py sets the Python call beside. threads: 0 a thread per core, as the
// faces' default; 1 for a steadier figure on a machine shared with other work.
void BM_FitSpaceFileLagunas3D(benchmark::State& state) {
  const auto file = nibrig::test::shared_data() / "lagunas2019" / "answers_processed_train.json";
  const space::SpaceInputs in = space::read_space_inputs(file, {}, 3, 0.0);
  space::SpaceFitSettings settings;
  settings.starts = 8;
  settings.threads = static_cast<unsigned>(state.range(0));
  for (auto _ : state) {
    const auto fitted = space::fit_space_file(in, file, {}, settings);
    benchmark::DoNotOptimize(fitted.file.objective);
    state.counters["objective"] = fitted.file.negative_log_likelihood;
  }
}

// One start on one thread for each judgment model, beside tests/bench/numpy_space_fit.py (numpy and
// scipy's L-BFGS-B on the same data, models and starts): seconds per start, and the optimum, so the
// two are known to reach the same place.
void BM_SpaceStartLagunas3D(benchmark::State& state) {
  static const io::TripletSet set = io::read_lagunas_json(
      nibrig::test::shared_data() / "lagunas2019" / "answers_processed_train.json");
  const char* families[] = {"probit", "logistic", "student-t", "probit+lapse+noise"};
  const char* family = families[state.range(0)];
  space::SpaceProblem p;
  p.dims = 3;
  p.stimuli = set.stimuli.size();
  p.triplets = set.triplets;
  p.model.family = space::parse_family(family);
  space::FitOptions options;
  options.starts = 1;
  options.threads = 1;
  options.spectral_start = false;  // random, as the reference's starts
  unsigned seed = 0;
  double best = 0.0, iterations = 0.0, evaluations = 0.0;
  for (auto _ : state) {
    options.seed = seed++;  // a new start each time, as the reference's three
    const auto fit = space::fit_space(p, options);
    best = seed == 1 ? fit.objective : std::min(best, fit.objective);
    iterations += fit.iterations;
    evaluations += fit.evaluations;
  }
  state.SetLabel(family);
  state.counters["objective"] = best;
  state.counters["iterations"] = iterations / static_cast<double>(seed);
  state.counters["evaluations"] = evaluations / static_cast<double>(seed);
}

// One evaluation of the objective and its gradient at a random 3-D space of Lagunas's stimuli, per
// judgment model, beside numpy_space_fit.py's per-evaluation time.
void BM_SpaceObjectiveLagunas3D(benchmark::State& state) {
  static const io::TripletSet set = io::read_lagunas_json(
      nibrig::test::shared_data() / "lagunas2019" / "answers_processed_train.json");
  const char* families[] = {"probit", "logistic", "student-t", "probit+lapse+noise"};
  space::SpaceProblem p;
  p.dims = 3;
  p.stimuli = set.stimuli.size();
  p.triplets = set.triplets;
  p.model.family = space::parse_family(families[state.range(0)]);
  if (p.model.family.lapse) p.model.lapse = 0.02;  // as a fit meets it: some lapse, typical noises
  if (p.model.family.stimulus_noise)
    p.model.log_noise = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(p.stimuli));
  const Eigen::MatrixXd q = Eigen::MatrixXd::Random(3, static_cast<Eigen::Index>(p.stimuli));
  Eigen::MatrixXd g;
  space::ModelGradient model_gradient;
  for (auto _ : state)
    benchmark::DoNotOptimize(space::objective(p, q, p.model, &g, &model_gradient));
  state.SetLabel(families[state.range(0)]);
  state.counters["ns_per_triplet"] = benchmark::Counter(
      static_cast<double>(p.triplets.size()),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_Bootstrap1000PaperSized2D(benchmark::State& state) {
  const space::SpaceProblem study = paper_sized_study();
  space::FitOptions fit_options;
  fit_options.starts = 16;
  const auto reference = space::fit_space(study, fit_options);
  space::BootstrapOptions options;
  options.resamples = 1000;
  for (auto _ : state) {
    const auto b = space::bootstrap_space(study, reference.coordinates, options);
    benchmark::DoNotOptimize(b.regions.front().radius.back());
  }
  state.counters["refits"] = options.resamples;
}

BENCHMARK(BM_FitPaperSizedStudy2D)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Bootstrap1000PaperSized2D)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_FitLagunas3D)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_FitSpaceFileLagunas3D)
    ->ArgName("threads")
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(BM_SpaceObjectiveLagunas3D)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SpaceStartLagunas3D)->DenseRange(0, 3)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace
