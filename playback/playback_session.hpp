// One presentation through the real-time engine: a tool, or the two or three of an A/B or triplet
// presentation, each a voice in its own slot, moved by one stroke, optionally through an actuator's
// inverse filter — then rendered to a WAV file or played on a device.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "model/io/velocity_spectrum.hpp"
#include "model/modal/modal_model.hpp"
#include "playback/actuator_file.hpp"
#include "playback/offline_render.hpp"
#include "rt/engine.hpp"
#include "rt/stroke_source.hpp"

namespace nibrig::playback {

// What a voice is made of: a stylus's modes driven by an acceleration spectrum (rt/voice_builder.hpp).
// The session builds the voice, so the references need to live only through its constructor.
struct SessionVoice {
  std::string name;
  const model::modal::ModalModel& modal;
  const model::io::VelocitySpectrum& spectrum;
};

class PlaybackSession {
 public:
  // An engine with `settings` (with a slot per voice), voice i with forcing
  // noise seeded seed + i in slot i, slot 0 selected and `stroke` attached. Throws
  // std::invalid_argument for no voice, no stroke, or what the engine and voice builder refuse.
  PlaybackSession(rt::EngineSettings settings, const std::vector<SessionVoice>& voices,
                  std::unique_ptr<rt::StrokeSource> stroke, std::uint64_t seed);

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
