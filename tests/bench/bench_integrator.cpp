// Throughput of the modal integrator in mode-samples per second (items/s): the exact
// piecewise-linear recursion rt/ runs on the audio thread, next to the naive way to get the same
// numbers, an Eigen matrix exponential of each mode's augmented 4×4 generator at every step.
// One second of 48 kHz noise force through a 64-mode stylus (paper's λ = 1.25e-3) per iteration;
// the naive run does 480 samples per iteration and is otherwise identical. Compare
// items_per_second, and the loop's share of the core's multiply-add rate (fma_peak_percent).
#include <benchmark/benchmark.h>

#include <Eigen/Dense>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <unsupported/Eigen/MatrixFunctions>
#include <vector>

#include "model/modal/linear_forcing_integrator.hpp"
#include "tests/bench/naive_modal_step.hpp"

namespace {

using nibrig::model::modal::LinearForcingIntegrator;
using nibrig::model::modal::ModalModel;

constexpr double kIntegratorRate = 48000.0;

// Modes log-spaced from 80 Hz to 20 kHz with ζ = λω/2 (λ = 1.25e-3), couplings of alternating sign.
ModalModel stylus(std::size_t modes) {
  ModalModel m;
  for (std::size_t i = 0; i < modes; ++i) {
    const double f = 80.0 * std::pow(250.0, static_cast<double>(i) / static_cast<double>(modes));
    const double w = 2.0 * std::numbers::pi * f;
    m.omega.push_back(w);
    m.zeta.push_back(nibrig::model::modal::rayleigh_damping_ratio(w, 0.0, 1.25e-3));
    m.input.push_back(i % 2 ? 0.8 : -1.1);
    m.output.push_back(i % 3 ? 0.5 : 1.3);
  }
  return m;
}

// LCG noise in [−1, 1) (Knuth's MMIX constants).
std::vector<float> noise(std::size_t n) {
  std::vector<float> x(n);
  std::uint64_t s = 1;
  for (auto& v : x) {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    v = static_cast<float>(static_cast<double>(s >> 11) * 0x1.0p-52 - 1.0);
  }
  return x;
}

// The core's own rate of double-precision fused multiply-adds with AVX2 (lane operations per
// second): twelve independent chains of four lanes, as many as keep both FMA units busy through
// their latency. The reference a mode loop's rate is set beside; 0 on a CPU without AVX2 and FMA.
#if defined(__x86_64__)
[[gnu::target("avx2,fma")]] double core_fma_lanes_per_second() {
  using Lanes = double __attribute__((vector_size(32)));
  constexpr int kChains = 12;
  constexpr std::int64_t kRounds = 20'000'000;
  Lanes acc[kChains];
  for (int c = 0; c < kChains; ++c) acc[c] = Lanes{1.0 + c, 2.0, 3.0, 4.0} * 1e-3;
  const Lanes a = {0.999999, 0.999999, 0.999999, 0.999999}, b = {1e-9, 1e-9, 1e-9, 1e-9};
  const auto start = std::chrono::steady_clock::now();
  for (std::int64_t r = 0; r < kRounds; ++r)
    for (int c = 0; c < kChains; ++c) acc[c] = acc[c] * a + b;
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (int c = 0; c < kChains; ++c) benchmark::DoNotOptimize(acc[c]);
  return static_cast<double>(kRounds * kChains * 4) / seconds;
}
#else
double core_fma_lanes_per_second() { return 0.0; }
#endif

// A mode-sample is 11 multiply-adds on one lane: 4 for the displacement, 4 for the velocity, 3 for
// its share of the output (linear_forcing_integrator.cpp, march()).
constexpr double kMultiplyAddsPerModeSample = 11.0;

// modes, and which loop: 0 the portable one, 1 the AVX2 and FMA one (when the CPU has them).
void BM_IntegratorPiecewiseLinear(benchmark::State& state) {
  const auto modes = static_cast<std::size_t>(state.range(0));
  LinearForcingIntegrator integrator(stylus(modes), kIntegratorRate);
  const bool vector = state.range(1) != 0;
  if (vector && integrator.kernel() != LinearForcingIntegrator::Kernel::avx2_fma) {
    state.SkipWithError("this CPU has no AVX2 and FMA");
    return;
  }
  if (!vector) integrator.set_kernel(LinearForcingIntegrator::Kernel::portable);
  const std::vector<float> force = noise(48000);
  std::vector<float> acceleration(force.size());
  const auto start = std::chrono::steady_clock::now();
  for (auto _ : state) {
    // rt/ calls process() with audio periods; 64 samples is a typical JACK period.
    for (std::size_t at = 0; at < force.size(); at += 64)
      integrator.process(force.data() + at, acceleration.data() + at, 64);
    benchmark::DoNotOptimize(acceleration.data());
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double items =
      static_cast<double>(state.iterations()) * static_cast<double>(modes * force.size());
  state.SetItemsProcessed(static_cast<std::int64_t>(items));
  state.counters["modes"] = static_cast<double>(modes);
  static const double peak = core_fma_lanes_per_second();
  state.counters["core_fma_lanes_per_s"] = peak;
  if (peak > 0)
    state.counters["fma_peak_percent"] =
        100.0 * items * kMultiplyAddsPerModeSample / seconds / peak;
}
BENCHMARK(BM_IntegratorPiecewiseLinear)
    ->ArgNames({"modes", "avx2"})
    ->ArgsProduct({{8, 64, 256}, {0, 1}})
    ->Unit(benchmark::kMillisecond);

void BM_IntegratorNaiveMatrixExponential(benchmark::State& state) {
  // Per mode and step: exp of h·[[0, 1, 0, 0], [−ω², −2ζω, b, 0], [0, 0, 0, 1], [0, 0, 0, 0]] on
  // [q, q̇, f, f'], then one product. Same arithmetic result as the recursion, none of the reuse.
  const auto modes = static_cast<std::size_t>(state.range(0));
  const ModalModel m = stylus(modes);
  const std::vector<float> force = noise(480);
  std::vector<Eigen::Vector2d> x(modes, Eigen::Vector2d::Zero());
  std::vector<float> acceleration(force.size());
  const double h = 1.0 / kIntegratorRate;
  for (auto _ : state) {
    for (std::size_t n = 1; n < force.size(); ++n) {
      const double f0 = force[n - 1], f1 = force[n];
      const double a = nibrig::bench::naive_modal_step(m, x, f0, f1, h);
      acceleration[n] = static_cast<float>(a);
    }
    benchmark::DoNotOptimize(acceleration.data());
  }
  state.SetItemsProcessed(state.iterations() *
                          static_cast<std::int64_t>(modes * (force.size() - 1)));
  state.counters["modes"] = static_cast<double>(modes);
}
BENCHMARK(BM_IntegratorNaiveMatrixExponential)->Arg(64)->Unit(benchmark::kMillisecond);

}  // namespace
