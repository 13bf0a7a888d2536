// How fast a rig that computes or replays its data hands it out: in step with the clock (a
// turntable turns in real time), k times faster, or as fast as it is computed (speedup 0). The
// simulated and replay rigs share it, so both behave like the real rig behind a capture.
#pragma once

#include <chrono>
#include <cstdint>

namespace nibrig::rig {

class Pacer {
 public:
  // `frame_rate_hz` > 0, `speedup` >= 0 (checked by the rigs that own one).
  Pacer(double speedup, double frame_rate_hz) : speedup_(speedup), frame_rate_(frame_rate_hz) {}

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
