#include "rig/live_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rig/acceleration_engine.hpp"

namespace nibrig::rig {

LiveSimulation::LiveSimulation(const model::design::ToolSound& sound, double acceleration_rate_hz,
                               double frame_rate_hz, std::uint64_t seed) {
  if (!(acceleration_rate_hz > 0.0) || !(frame_rate_hz > 0.0) || !std::isfinite(acceleration_rate_hz) ||
      !std::isfinite(frame_rate_hz))
    throw std::invalid_argument("live simulation: rates must be positive");
  samples_per_frame_ = acceleration_rate_hz / frame_rate_hz;
  // The engine starts with the live contact at rest and follows every set_contact.
  session_ = acceleration_engine(sound, acceleration_rate_hz,
                                 std::make_unique<rt::ConstantStroke>(0.0, 0.0), seed);
  pending_.reserve(4096);
}

LiveSimulation::~LiveSimulation() = default;

void LiveSimulation::feed(const RigData& data, std::vector<float>& simulated_m_s2) {
  pending_.insert(pending_.end(), data.frames.begin(), data.frames.end());
  rt::Engine& engine = session_->engine();
  const std::uint64_t target = samples_ + data.acceleration.size();
  while (samples_ < target) {
    // The frame whose span holds the next sample, and where that span ends.
    const auto k = static_cast<std::uint64_t>(std::floor(static_cast<double>(samples_) / samples_per_frame_));
    std::uint64_t end = target;
    if (k >= first_ && k - first_ < pending_.size()) {
      const SensorFrame& f = pending_[k - first_];
      // The queue drains at every render, so it has room (one command per frame).
      engine.set_contact(std::max(0.0f, f.speed_m_s), std::max(0.0f, f.normal_force_N));
      end = std::min<std::uint64_t>(
          target, static_cast<std::uint64_t>(std::ceil(static_cast<double>(k + 1) * samples_per_frame_)));
    }
    const std::size_t count = std::max<std::uint64_t>(1, end - samples_);
    block_.resize(count);
    engine.render(block_.data(), count);
    for (float x : block_) simulated_m_s2.push_back(static_cast<float>(x * kEngineHeadroom_m_s2));
    samples_ += count;
    engine.collect();  // the stroke the first contact detached, freed here, off any audio thread
  }
  // Frames wholly rendered are done with.
  const auto done = static_cast<std::uint64_t>(std::floor(static_cast<double>(samples_) / samples_per_frame_));
  if (done > first_) {
    const std::uint64_t drop = std::min<std::uint64_t>(done - first_, pending_.size());
    pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(drop));
    first_ += drop;
  }
}

}  // namespace nibrig::rig
