#include "playback/prepared_engine.hpp"

#include <algorithm>
#include <stdexcept>

#include "rt/fir_filter.hpp"
#include "rt/voice_builder.hpp"

namespace nibrig::playback {

PreparedEngine::PreparedEngine(rt::EngineSettings settings,
                               std::span<const model::modal::VoiceSource> voices,
                               std::unique_ptr<rt::StrokeSource> stroke, std::uint64_t seed) {
  if (voices.empty()) throw std::invalid_argument("a prepared engine needs at least one voice");
  if (!stroke) throw std::invalid_argument("a prepared engine needs a stroke");
  settings.slots = voices.size();
  engine_ = std::make_unique<rt::Engine>(settings);
  // Nothing renders yet, so the queues are empty and take every command.
  for (std::size_t i = 0; i < voices.size(); ++i) {
    auto voice = rt::build_voice(voices[i], engine_->internal_rate(), seed + i);
    names_.push_back(voice->name());
    engine_->load(i, std::move(voice));
  }
  engine_->select(0);
  engine_->attach(std::move(stroke));
}

InverseFilter PreparedEngine::use_actuator(const ActuatorCalibration& calibration) {
  InverseFilter filter = redesign_for_rate(calibration, engine_->internal_rate());
  engine_->set_calibration(std::make_unique<rt::FirFilter>(filter.taps));
  engine_->set_output_level(1.0);  // the filter turns m/s² into output level
  return filter;
}

OfflineRenderResult PreparedEngine::render_to_wav(const std::filesystem::path& wav, double seconds,
                                                   std::size_t block_frames) {
  OfflineRenderSettings settings;
  settings.sample_rate_hz = engine_->sample_rate();
  settings.block_frames = block_frames;
  settings.seconds = seconds;
  return playback::render_to_wav(*engine_, wav, settings);
}

}  // namespace nibrig::playback
