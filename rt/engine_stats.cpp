#include "rt/engine_stats.hpp"

#include <cmath>

namespace nibrig::rt {

double callback_time_bin_edge(std::size_t bin) {
  return bin == 0 ? 0.0 : 1e-6 * std::pow(10.0, (static_cast<double>(bin) - 1.0) / 10.0);
}

std::size_t callback_time_bin(double seconds) {
  if (!(seconds >= 1e-6)) return 0;
  const auto bin = static_cast<std::size_t>(std::floor(10.0 * std::log10(seconds / 1e-6))) + 1;
  return bin < kCallbackTimeBins ? bin : kCallbackTimeBins - 1;
}

double EngineStats::callback_time_quantile(double q) const {
  std::uint64_t total = 0;
  for (auto n : callback_time_histogram) total += n;
  if (total == 0) return 0.0;
  const double wanted = q * static_cast<double>(total);
  std::uint64_t seen = 0;
  for (std::size_t b = 0; b < kCallbackTimeBins; ++b) {
    seen += callback_time_histogram[b];
    if (static_cast<double>(seen) >= wanted)
      return b + 1 < kCallbackTimeBins ? callback_time_bin_edge(b + 1) : max_callback_s;
  }
  return max_callback_s;
}

EngineStats AtomicEngineStats::snapshot() const {
  constexpr auto relaxed = std::memory_order_relaxed;
  EngineStats s;
  s.callbacks = callbacks.load(relaxed);
  s.frames = frames.load(relaxed);
  s.overruns = overruns.load(relaxed);
  s.device_xruns = device_xruns.load(relaxed);
  s.max_callback_s = max_callback_s.load(relaxed);
  s.max_callback_cpu_s = max_callback_cpu_s.load(relaxed);
  for (std::size_t b = 0; b < kCallbackTimeBins; ++b)
    s.callback_time_histogram[b] = callback_time_histogram[b].load(relaxed);
  s.peak_output = peak_output.load(relaxed);
  s.limited_samples = limited_samples.load(relaxed);
  s.non_finite_samples = non_finite_samples.load(relaxed);
  s.samples_above_speed_range = samples_above_speed_range.load(relaxed);
  s.voices = voices.load(relaxed);
  s.refused_commands = refused_commands.load(relaxed);
  return s;
}

}  // namespace nibrig::rt
