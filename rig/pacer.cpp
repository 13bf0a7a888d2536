#include "rig/pacer.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace nibrig::rig {

void Pacer::check_speedup(double speedup, const char* who) {
  if (speedup == 0.0 || (speedup >= kMinSpeedup && speedup <= kMaxSpeedup)) return;
  std::ostringstream message;
  if (who != nullptr) message << who << ": ";
  message << "speed-up " << speedup << ": expected 0 (as fast as it computes) or " << kMinSpeedup
          << " to " << kMaxSpeedup << " (1: real time)";
  throw std::invalid_argument(message.str());
}

Pacer::Pacer(double speedup, double frame_rate_hz) : speedup_(speedup), frame_rate_(frame_rate_hz) {
  check_speedup(speedup, "rig pacing");
}

std::uint64_t Pacer::due_at(std::chrono::steady_clock::time_point when) const {
  const double elapsed = std::chrono::duration<double>(when - started_).count();
  return static_cast<std::uint64_t>(std::max(0.0, elapsed * speedup_ * frame_rate_));
}

std::uint64_t Pacer::due(std::uint64_t made, std::uint64_t total, std::uint64_t block,
                         std::uint64_t unpaced_chunk, std::chrono::milliseconds wait) const {
  if (speedup_ <= 0.0) return std::min(total, made + unpaced_chunk);
  std::uint64_t due = std::min(total, due_at(std::chrono::steady_clock::now()));
  if (due < made + block && due < total) {  // nothing whole yet: sleep until a block is due
    const double next_s = static_cast<double>(made + block) / (speedup_ * frame_rate_);
    const auto next = started_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                     std::chrono::duration<double>(next_s));
    std::this_thread::sleep_until(std::min(next, std::chrono::steady_clock::now() + wait));
    due = std::min(total, due_at(std::chrono::steady_clock::now()));
  }
  return due;
}

}  // namespace nibrig::rig
