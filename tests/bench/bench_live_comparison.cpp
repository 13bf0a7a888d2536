// What the live comparison costs its analysis thread: the streaming spectrograms of a 48 kHz
// measured and simulated stream, fed in audio-sized blocks, each row pair added to the speed-binned
// comparison, and the per-bin table recomputed ten times a second as the thread publishes it. The
// `core_percent` counter is the analysing thread's own CPU time per second of audio, in percent of
// one core (the thread's clock, so that other load on the machine does not count): the budget is
// < 5 %.
#include <benchmark/benchmark.h>
#include <time.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "model/measure/speed_binned_comparison.hpp"
#include "model/measure/streaming_spectrogram.hpp"

namespace {

namespace measure = nibrig::model::measure;

constexpr double kComparisonRate = 48000.0;
constexpr std::size_t kSeconds = 10;
constexpr std::size_t kBlock = 256;  // a typical audio period

double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

measure::ThresholdCurve threshold() {
  return measure::ThresholdCurve({10.0, 250.0, 1000.0}, {0.05, 0.005, 0.1}, "bench curve");
}

void BM_LiveComparisonAnalysis(benchmark::State& state) {
  const auto length = static_cast<std::size_t>(state.range(0));
  const measure::SpectrogramSettings settings{length, length / 4, measure::Window::hann, true};
  std::mt19937 rng(1);
  std::normal_distribution<double> noise(0.0, 0.2);
  std::vector<float> measured(kSeconds * 48000), simulated(measured.size());
  for (std::size_t n = 0; n < measured.size(); ++n) {
    const double t = static_cast<double>(n) / kComparisonRate;
    measured[n] = static_cast<float>(std::sin(2 * std::numbers::pi * 180.0 * t) + noise(rng));
    simulated[n] =
        static_cast<float>(0.8 * std::sin(2 * std::numbers::pi * 190.0 * t) + noise(rng));
  }
  measure::StreamingSpectrogram a(kComparisonRate, settings), b(kComparisonRate, settings);
  measure::SpeedBinnedComparison comparison(a.frequencies_hz(), {}, threshold());
  std::vector<double> pending(a.bins());
  const std::size_t publish_every = static_cast<std::size_t>(kComparisonRate / 10.0);
  double lsd = 0.0;
  const double cpu_start = thread_cpu_seconds();
  for (auto _ : state) {
    a.reset();
    b.reset();
    comparison.reset();
    for (std::size_t pos = 0; pos < measured.size(); pos += kBlock) {
      a.push(std::span<const float>(measured).subspan(pos, kBlock),
             [&](const measure::SpectrogramRow& row) {
               std::copy(row.amplitude.begin(), row.amplitude.end(), pending.begin());
             });
      b.push(std::span<const float>(simulated).subspan(pos, kBlock),
             [&](const measure::SpectrogramRow& row) {
               // A speed sweeping the bins, as a turntable profile would.
               const double speed = 0.017 + 0.233 * static_cast<double>(row.index % 200) / 200.0;
               comparison.add(speed, pending, row.amplitude);
             });
      if ((pos + kBlock) % publish_every < kBlock) lsd = comparison.summary().mean_lsd_db;
    }
    benchmark::DoNotOptimize(lsd);
  }
  const double cpu = thread_cpu_seconds() - cpu_start;
  state.counters["lsd_db"] = lsd;
  state.counters["core_percent"] = 100.0 * cpu / static_cast<double>(state.iterations() * kSeconds);
}

BENCHMARK(BM_LiveComparisonAnalysis)->Arg(1024)->Arg(4096)->Unit(benchmark::kMillisecond);

}  // namespace
