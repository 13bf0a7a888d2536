// An engine made ready before it runs: a voice per slot (a tool, or the two or three of an A/B or
// triplet presentation), one stroke, optionally an actuator's inverse filter. Its owner renders it:
// into a WAV file, or block by block as the rig's simulation does. What plays while a person
// works, and changes tools as they choose, is the LiveAudition (live_audition.hpp).
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "model/modal/voice_source.hpp"
#include "playback/actuator_file.hpp"
#include "playback/offline_render.hpp"
#include "rt/engine.hpp"
#include "rt/stroke_source.hpp"

namespace nibrig::playback {

class PreparedEngine {
 public:
  // An engine with `settings` (with a slot per voice), the voice of voices[i] (rt::build_voice)
  // with forcing noise seeded seed + i in slot i, slot 0 selected and `stroke` attached. The voices
  // are built here, so `voices` need live only through the constructor. Throws
  // std::invalid_argument for no voice, no stroke, or what the engine and voice builder refuse.
  PreparedEngine(rt::EngineSettings settings, std::span<const model::modal::VoiceSource> voices,
                 std::unique_ptr<rt::StrokeSource> stroke, std::uint64_t seed);
  PreparedEngine(rt::EngineSettings settings, const model::modal::VoiceSource& voice,
                 std::unique_ptr<rt::StrokeSource> stroke, std::uint64_t seed)
      : PreparedEngine(settings, std::span(&voice, 1), std::move(stroke), seed) {}

  rt::Engine& engine() noexcept { return *engine_; }
  const std::vector<std::string>& names() const noexcept { return names_; }

  // Runs the mix through the actuator's inverse filter, redesigned for the engine's internal
  // rate; the output level becomes a trim (1 = as calibrated). Returns the filter it designed,
  // whose flatness a face reports.
  InverseFilter use_actuator(const ActuatorCalibration& calibration);

  // `seconds` of output in blocks of `block_frames` into a float WAV (offline_render.hpp).
  OfflineRenderResult render_to_wav(const std::filesystem::path& wav, double seconds,
                                    std::size_t block_frames);

 private:
  std::unique_ptr<rt::Engine> engine_;
  std::vector<std::string> names_;
};

}  // namespace nibrig::playback
