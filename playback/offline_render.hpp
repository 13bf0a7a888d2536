// Rendering without a device: the engine's render() called block by block exactly as an audio
// callback would, into a 32-bit float WAV. The same code path as real-time playback, so a render
// and a device fed the same inputs produce the same samples.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

#include "rt/block_renderer.hpp"
#include "rt/stroke_request.hpp"

namespace nibrig::playback {

// The ranges a render is held to, by every face (the command line's options check the same
// numbers): so that neither 1e308 nor 1e-300 starts a render that never ends or means nothing.
// The voices run at about 8 kHz (rt/engine.hpp): a device rate below that cannot carry them.
inline constexpr double kLowestRenderRateHz = 8000.0, kHighestRenderRateHz = 384000.0;
inline constexpr std::size_t kLargestRenderBlock = std::size_t{1} << 16;  // a device period's largest
inline constexpr double kShortestRenderSeconds = 0.001, kLongestRenderSeconds = 3600.0;
// A constant stroke: 0 (at rest, lifted) or these. The paper measured 17-250 mm/s at 2.2 N; the
// ends are a hand's slowest crawl and fastest flick, a feather's touch and a tip's breaking load.
inline constexpr double kSlowestStrokeM_s = 1e-5, kFastestStrokeM_s = 10.0;
inline constexpr double kLightestStrokeN = 0.001, kHeaviestStrokeN = 50.0;

// Throw std::invalid_argument "<who>: <value> <unit>: expected ..." for a value outside the ranges
// above (or not finite); `who` is the option or argument that set it ("--rate", "rate_hz").
void check_render_rate(double rate_hz, const std::string& who);
void check_render_block(std::size_t frames, const std::string& who);
void check_render_seconds(double seconds, const std::string& who);
// A stroke's constant speed and force, named "speed" and "force".
void check_stroke_request(const rt::StrokeRequest& request);

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
// failure, std::invalid_argument for a rate, block or duration outside the ranges above.
OfflineRenderResult render_to_wav(rt::BlockRenderer& renderer, const std::filesystem::path& wav,
                                  const OfflineRenderSettings& settings);

}  // namespace nibrig::playback
