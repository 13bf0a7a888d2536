#include "rig/contact_follower.hpp"

#include <algorithm>
#include <chrono>

namespace nibrig::rig {
namespace {

std::int64_t now_ns() noexcept {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

}  // namespace

void ContactFollower::follow(const SensorFrame& frame) noexcept {
  const std::int64_t origin = frame.host_ns != 0 ? frame.host_ns : now_ns();
  if (engine_.set_contact(std::max(0.0f, frame.speed_m_s), std::max(0.0f, frame.normal_force_N)))
    posted_origin_ns_.store(origin, std::memory_order_release);
}

void ContactFollower::render(float* out, std::size_t frames) noexcept {
  const std::int64_t origin = posted_origin_ns_.load(std::memory_order_acquire);
  if (origin != applied_origin_ns_ && origin != 0) {
    // The engine takes the posted contact at the start of this block: it waited until now.
    const std::int64_t waited = std::max<std::int64_t>(0, now_ns() - origin);
    applied_origin_ns_ = origin;
    contacts_.fetch_add(1, std::memory_order_relaxed);
    total_ns_.fetch_add(waited, std::memory_order_relaxed);
    if (waited > max_ns_.load(std::memory_order_relaxed)) max_ns_.store(waited, std::memory_order_relaxed);
  }
  engine_.render(out, frames);
}

FollowLatency ContactFollower::latency() const noexcept {
  FollowLatency l;
  l.contacts = contacts_.load(std::memory_order_relaxed);
  if (l.contacts > 0)
    l.mean_s = static_cast<double>(total_ns_.load(std::memory_order_relaxed)) * 1e-9 /
               static_cast<double>(l.contacts);
  l.max_s = static_cast<double>(max_ns_.load(std::memory_order_relaxed)) * 1e-9;
  return l;
}

}  // namespace nibrig::rig
