#include "rig/actuator_player.hpp"

#include "playback/actuator_store.hpp"
#include "playback/prepared_engine.hpp"
#include "rt/stroke_source.hpp"

namespace nibrig::rig {

ActuatorPlayer::ActuatorPlayer(Rig& rig, const model::design::ToolSound& sound,
                               const ActuatorPlayerSettings& settings)
    : rig_(rig), settings_(settings), sound_name_(sound.name) {
  rt::EngineSettings engine;
  engine.sample_rate_hz = settings.device.sample_rate;
  engine.slots = 1;
  engine_ = std::make_unique<playback::PreparedEngine>(
      engine, sound, std::make_unique<rt::ConstantStroke>(0.0, 0.0), settings.seed);
  if (!settings.actuator.empty()) {
    calibration_ = playback::read_actuator_file(playback::find_actuator(settings.actuator));
    filter_ = engine_->use_actuator(*calibration_);
  }
  follower_ = std::make_unique<ContactFollower>(engine_->engine());
  listener_ = [this](const SensorFrame& f) { follower_->follow(f); };
  rig_.set_frame_listener(&listener_);
}

ActuatorPlayer::~ActuatorPlayer() {
  rig_.set_frame_listener(nullptr);
  stop();
}

void ActuatorPlayer::play() {
  if (!output_) output_ = std::make_unique<playback::AudioOutput>(*follower_, settings_.device);
}

void ActuatorPlayer::stop() noexcept { output_.reset(); }

std::optional<playback::StreamInfo> ActuatorPlayer::stream_info() const {
  if (!output_) return std::nullopt;
  return output_->stream_info();
}

std::optional<playback::OutputStatus> ActuatorPlayer::output_status() const {
  if (!output_) return std::nullopt;
  return output_->status();
}

std::string ActuatorPlayer::last_problem() const { return output_ ? output_->last_problem() : std::string(); }

}  // namespace nibrig::rig
