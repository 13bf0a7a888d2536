// Rendering without a device: the engine's render() called block by block exactly as an audio
// callback would, into a 32-bit float WAV. The same code path as real-time playback, so a render
// and a device fed the same inputs produce the same samples.
#pragma once

#include <cstddef>
#include <filesystem>

#include "rt/block_renderer.hpp"

namespace nibrig::playback {

struct OfflineRenderSettings {
  double sample_rate_hz = 48000.0;
  std::size_t block_frames = 64;  // the period the real-time path would use
  double seconds = 6.0;
};

struct OfflineRenderResult {
  std::size_t frames = 0;
  double peak = 0.0;  // largest |sample|
  double rms = 0.0;
};

// Writes `seconds` of renderer output to `wav` (mono, float). The file is written as
// "<wav>.partial" with its header kept current, so a process killed mid-render still leaves a
// readable file, and renamed to `wav` when complete; on any error the ".partial" is removed before
// the exception leaves, so a failed render leaves no file. The folder must exist. Throws std::runtime_error naming the file on an I/O
// failure, std::invalid_argument for a non-positive rate, block or duration.
OfflineRenderResult render_to_wav(rt::BlockRenderer& renderer, const std::filesystem::path& wav,
                                  const OfflineRenderSettings& settings);

}  // namespace nibrig::playback
