// The actuator follows the turntable: each measured frame's speed and normal force go to the playing
// engine's live contact as it arrives (rt::Engine::set_contact, a lock-free post), and the engine
// takes it at the start of its next block. Wrapped around the engine as the device's renderer, it
// also measures what that costs: from the frame's arrival on the host (the USB driver's stamp) or
// its post, to the block that applied it.
#pragma once

#include <atomic>
#include <cstdint>

#include "rig/sensor_frame.hpp"
#include "rt/block_renderer.hpp"
#include "rt/engine.hpp"

namespace nibrig::rig {

struct FollowLatency {
  std::uint64_t contacts = 0;  // frames a block applied (later posts supersede earlier ones)
  double mean_s = 0.0, max_s = 0.0;
};

class ContactFollower final : public rt::BlockRenderer {
 public:
  explicit ContactFollower(rt::Engine& engine) : engine_(engine) {}

  // Control side (one thread: the rig's event thread or the capture's). Never blocks; when the
  // engine's queue is full the frame is dropped, the next one superseding it anyway.
  void follow(const SensorFrame& frame) noexcept;

  // Audio side: the engine's block, noting how long the newest post waited for it.
  void render(float* out, std::size_t frames) noexcept override;

  FollowLatency latency() const noexcept;

 private:
  rt::Engine& engine_;
  std::atomic<std::int64_t> posted_origin_ns_{0};  // arrival (or post) of the newest frame posted
  std::int64_t applied_origin_ns_ = 0;             // audio thread only
  std::atomic<std::uint64_t> contacts_{0};
  std::atomic<std::int64_t> total_ns_{0}, max_ns_{0};
};

}  // namespace nibrig::rig
