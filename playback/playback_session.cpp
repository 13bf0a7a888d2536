#include "playback/playback_session.hpp"

#include <algorithm>
#include <stdexcept>

#include "rt/fir_filter.hpp"
#include "rt/voice_builder.hpp"

namespace nibrig::playback {

PlaybackSession::PlaybackSession(rt::EngineSettings settings, const std::vector<SessionVoice>& voices,
                                 std::unique_ptr<rt::StrokeSource> stroke, std::uint64_t seed) {
  if (voices.empty()) throw std::invalid_argument("a playback session needs at least one voice");
  if (!stroke) throw std::invalid_argument("a playback session needs a stroke");
  settings.slots = voices.size();
  engine_ = std::make_unique<rt::Engine>(settings);
  // Nothing renders yet, so the queues are empty and take every command.
  for (std::size_t i = 0; i < voices.size(); ++i) {
    auto voice = rt::build_voice(voices[i].name, voices[i].modal, voices[i].spectrum,
                                 engine_->internal_rate(), seed + i);
    names_.push_back(voice->name());
    engine_->load(i, std::move(voice));
  }
  engine_->select(0);
  engine_->attach(std::move(stroke));
}

InverseFilter PlaybackSession::use_actuator(const ActuatorCalibration& calibration) {
  InverseFilter filter = redesign_for_rate(calibration, engine_->internal_rate());
  engine_->set_calibration(std::make_unique<rt::FirFilter>(filter.taps));
  engine_->set_output_level(1.0);  // the filter turns m/s² into output level
  return filter;
}

OfflineRenderResult PlaybackSession::render_to_wav(const std::filesystem::path& wav, double seconds,
                                                   std::size_t block_frames) {
  OfflineRenderSettings settings;
  settings.sample_rate_hz = engine_->sample_rate();
  settings.block_frames = block_frames;
  settings.seconds = seconds;
  return playback::render_to_wav(*engine_, wav, settings);
}

}  // namespace nibrig::playback
