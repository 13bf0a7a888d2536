// Spectrogram throughput on one minute of 48 kHz audio-rate signal, the size of a live rig capture,
// for the two segment lengths the panel uses. Compare with scipy: tests/bench/scipy_spectrogram.py
// builds the same input from the same formula and prints its time per call and the same checksum.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "model/measure/spectrogram.hpp"

namespace {

constexpr double kSpectrogramRate = 48000.0;
constexpr std::size_t kSamples = 60 * 48000;

// Two tones plus uniform noise from a 64-bit LCG (Knuth's MMIX constants), reproducible bit for bit
// in Python: x[n] = 0.5 sin(2π·440 n/fs) + 0.25 sin(2π·1234.5 n/fs) + ((s >> 11)·2⁻⁵³ - 0.5).
const std::vector<double>& input() {
  static const std::vector<double> x = [] {
    std::vector<double> v(kSamples);
    std::uint64_t s = 1;
    for (std::size_t n = 0; n < kSamples; ++n) {
      s = s * 6364136223846793005ULL + 1442695040888963407ULL;
      const double noise = static_cast<double>(s >> 11) * 0x1.0p-53 - 0.5;
      const double t = static_cast<double>(n) / kSpectrogramRate;
      v[n] = 0.5 * std::sin(2.0 * std::numbers::pi * 440.0 * t) +
             0.25 * std::sin(2.0 * std::numbers::pi * 1234.5 * t) + noise;
    }
    return v;
  }();
  return x;
}

void BM_Spectrogram(benchmark::State& state) {
  const auto length = static_cast<std::size_t>(state.range(0));
  const nibrig::model::measure::SpectrogramSettings settings{
      length, length / 4, nibrig::model::measure::Window::hann, true};  // 75 % overlap
  const auto& x = input();
  double checksum = 0.0;
  for (auto _ : state) {
    const auto sg = nibrig::model::measure::compute_spectrogram(x, kSpectrogramRate, settings);
    benchmark::DoNotOptimize(sg.amplitude.data());
    // The checksum (a pass over 46 MB) is not part of the spectrogram, and the Python script does
    // not time its own either; freeing the result at the end of the scope is timed in both.
    state.PauseTiming();
    checksum = sg.amplitude.sum();
    state.ResumeTiming();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kSamples));
  state.SetBytesProcessed(state.iterations() *
                          static_cast<std::int64_t>(kSamples * sizeof(double)));
  // Sum of all peak amplitudes: scipy's magnitude spectrogram is |X|/Σw without the one-sided
  // factor 2, so the Python script reports 2·(interior bins) + (DC and Nyquist bins) to compare.
  state.counters["checksum"] = checksum;
}

BENCHMARK(BM_Spectrogram)->Arg(1024)->Arg(4096)->Unit(benchmark::kMillisecond);

}  // namespace
