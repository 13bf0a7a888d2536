// What an audio back end (playback/) asks of the engine: fill the next block of mono output. Kept
// apart from the engine so that playback/ and its tests can drive any real-time source the same
// way, and so that the offline render and the device callback call exactly the same function.
#pragma once

#include <cstddef>

namespace nibrig::rt {

class BlockRenderer {
 public:
  virtual ~BlockRenderer() = default;
  // Writes `frames` samples to out (full scale = ±1). Called on the audio thread: must not
  // allocate, lock, log, block or throw.
  virtual void render(float* out, std::size_t frames) noexcept = 0;
};

}  // namespace nibrig::rt
