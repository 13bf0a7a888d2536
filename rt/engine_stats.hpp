// What the engine reports about itself while it runs: counts written by the audio thread with
// relaxed atomics (no locks) and read as a snapshot from any other thread, and the callback-time
// histogram from which the median and 99th percentile are read.
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>

namespace nibrig::rt {

// Log-spaced bins of callback time: bin b holds times in [edge(b), edge(b+1)), edge(0) = 0,
// edge(b) = 1 µs · 10^((b − 1)/10) for b ≥ 1 (ten bins per decade, 1 µs to 1 s); the last bin is
// open-ended.
inline constexpr std::size_t kCallbackTimeBins = 62;
double callback_time_bin_edge(std::size_t bin);  // seconds
std::size_t callback_time_bin(double seconds);

struct EngineStats {
  std::uint64_t callbacks = 0, frames = 0;
  // Blocks whose rendering took more CPU time than the block lasts: measured inside the callback,
  // so they are ours, unlike the device's xruns (which a shared machine without real-time
  // scheduling also causes). The histogram and max_callback_s are wall time, preemption included.
  std::uint64_t overruns = 0;
  std::uint64_t device_xruns = 0;  // reported by the audio back end (playback/)
  double max_callback_s = 0;
  // The largest CPU time of one block (what overruns compare), an upper bound: a block within its
  // period counts its wall time, and one past it at most period/8 more than its own
  // (BlockCpuClock).
  double max_callback_cpu_s = 0;
  std::array<std::uint64_t, kCallbackTimeBins> callback_time_histogram{};
  double peak_output = 0;                 // largest |sample| sent to the device (full scale 1)
  std::uint64_t limited_samples = 0;      // samples the limiter attenuated
  std::uint64_t non_finite_samples = 0;   // NaN/inf replaced by silence
  std::uint64_t samples_above_speed_range = 0;  // internal samples at speeds above a table's
  std::size_t voices = 0;                 // voices running (selected, fading or waiting warm)
  std::uint64_t refused_commands = 0;     // control calls refused because a queue was full

  // The time below which a fraction q of callbacks finished (the upper edge of the bin holding
  // the q-quantile); 0 when there were none.
  double callback_time_quantile(double q) const;
};

// The audio thread's side: every field an atomic, updated at the end of each block.
struct AtomicEngineStats {
  std::atomic<std::uint64_t> callbacks{0}, frames{0}, overruns{0}, device_xruns{0};
  std::atomic<double> max_callback_s{0}, max_callback_cpu_s{0};
  std::array<std::atomic<std::uint64_t>, kCallbackTimeBins> callback_time_histogram{};
  std::atomic<double> peak_output{0};
  std::atomic<std::uint64_t> limited_samples{0}, non_finite_samples{0},
      samples_above_speed_range{0};
  std::atomic<std::size_t> voices{0};
  std::atomic<std::uint64_t> refused_commands{0};

  EngineStats snapshot() const;
};

}  // namespace nibrig::rt
