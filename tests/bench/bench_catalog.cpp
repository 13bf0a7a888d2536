// Time to build the whole catalog from the paper's recordings (../shared/data/piovarci2018):
// reading every friction and accelerometer file, detecting contact and speed steps, fitting μ,
// velocity-binned spectra and descriptors. Threads: 1 and one per core.
#include <benchmark/benchmark.h>

#include <thread>

#include "model/catalog/catalog_builder.hpp"
#include "tests/support/test_paths.hpp"

namespace {

void BM_BuildPaperCatalog(benchmark::State& state) {
  namespace catalog = nibrig::model::catalog;
  const auto root = nibrig::test::shared_data() / "piovarci2018";
  const auto threshold = nibrig::model::measure::ThresholdCurve::load(
      nibrig::test::assets_dir() / "thresholds/israr2006_pen_hold.csv");
  const auto found = catalog::find_recordings(root);
  const auto threads = static_cast<unsigned>(state.range(0));
  const catalog::AnalysisOptions options;
  for (auto _ : state) {
    auto build = catalog::build_catalog(found, threshold, options, threads);
    benchmark::DoNotOptimize(build.catalog.pairings.data());
  }
  state.counters["files"] = static_cast<double>(found.files.size());
  state.counters["files_per_s"] = benchmark::Counter(
      static_cast<double>(found.files.size()) * static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate);
}

BENCHMARK(BM_BuildPaperCatalog)
    ->Arg(1)
    ->Arg(static_cast<int>(std::max(1u, std::thread::hardware_concurrency())))
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->UseRealTime();

}  // namespace
