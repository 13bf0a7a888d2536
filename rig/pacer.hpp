// How fast a rig that computes or replays its data hands it out: in step with the clock (a
// turntable turns in real time), k times faster, or as fast as it is computed (speedup 0). The
// simulated and replay rigs share it, so both behave like the real rig behind a capture.
#pragma once

#include <chrono>
#include <cstdint>

namespace nibrig::rig {

class Pacer {
 public:
  // A speed-up is 0 (unpaced) or in [kMinSpeedup, kMaxSpeedup]: a hundred times slower than real
  // time is as slow as anyone watches a rig, and below that a capture would not end in a day.
  static constexpr double kMinSpeedup = 0.01;
  static constexpr double kMaxSpeedup = 1e6;
  // Throws std::invalid_argument "<who>: speed-up X: expected 0 or 0.01 to 1e+06 ..." (who null:
  // without it).
  static void check_speedup(double speedup, const char* who);

  // `frame_rate_hz` > 0; throws for a speed-up check_speedup refuses.
  Pacer(double speedup, double frame_rate_hz);

  void start() { started_ = std::chrono::steady_clock::now(); }

  // How many frames (of `total`) may have been delivered now, given `made` already: waits (at most
  // `wait`) until at least a whole block of `block` frames more is due, or the end. Unpaced, a
  // block of `unpaced_chunk` frames more.
  std::uint64_t due(std::uint64_t made, std::uint64_t total, std::uint64_t block,
                    std::uint64_t unpaced_chunk, std::chrono::milliseconds wait) const;

 private:
  std::uint64_t due_at(std::chrono::steady_clock::time_point when) const;

  double speedup_, frame_rate_;
  std::chrono::steady_clock::time_point started_;
};

}  // namespace nibrig::rig
