// A simulated tool played on the actuator while a rig runs: its engine follows each measured frame's
// speed and force as the frame arrives (rig/contact_follower.hpp), on an audio device by name, through
// the actuator's inverse filter when a calibration is given. The device opens and closes while the
// rig runs, so a face can turn the playing on and off; the engine keeps following either way.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "model/design/tool_sound.hpp"
#include "playback/actuator_file.hpp"
#include "playback/audio_output.hpp"
#include "playback/inverse_filter.hpp"
#include "rig/contact_follower.hpp"
#include "rig/rig.hpp"

namespace nibrig::playback {
class PreparedEngine;
}

namespace nibrig::rig {

struct ActuatorPlayerSettings {
  playback::OutputSettings device;  // its sample rate is the engine's
  std::string actuator;             // a stored calibration's name or an actuator file; empty: none
  std::uint64_t seed = 1;           // the forcing noise
};

class ActuatorPlayer {
 public:
  // Makes the engine (one voice of `sound`, at rest until a frame moves it) and listens to `rig`'s
  // frames from now on: made before rig.start(), it must outlive the run. Throws what
  // playback::find_actuator and read_actuator_file throw for the actuator, and what the engine
  // throws for the sound. Nothing sounds until play().
  ActuatorPlayer(Rig& rig, const model::design::ToolSound& sound, const ActuatorPlayerSettings& settings);
  // Stops listening to the rig and closes the device.
  ~ActuatorPlayer();
  ActuatorPlayer(const ActuatorPlayer&) = delete;
  ActuatorPlayer& operator=(const ActuatorPlayer&) = delete;

  // Opens the device, when it is not open, and plays on it. Throws playback::DeviceError naming
  // what was asked. play() and stop() are called from one control thread.
  void play();
  // Closes the device: the actuator falls silent while the engine keeps following the frames.
  void stop() noexcept;
  bool playing() const noexcept { return output_ != nullptr; }

  const std::string& sound_name() const noexcept { return sound_name_; }
  const playback::OutputSettings& device() const noexcept { return settings_.device; }
  // The calibration played through and the inverse filter designed from it; nullopt without one.
  const std::optional<playback::ActuatorCalibration>& actuator() const noexcept { return calibration_; }
  const std::optional<playback::InverseFilter>& inverse_filter() const noexcept { return filter_; }
  // Of the device while playing; nullopt otherwise.
  std::optional<playback::StreamInfo> stream_info() const;
  // The stream's state while it plays (lost: the device went away and is looked for again), and
  // why it was last lost; nullopt and empty while stopped. Any thread that also calls play().
  std::optional<playback::OutputStatus> output_status() const;
  std::string last_problem() const;
  // From each frame's arrival to the audio block that applied it, over everything followed so far.
  FollowLatency latency() const { return follower_->latency(); }

 private:
  Rig& rig_;
  ActuatorPlayerSettings settings_;
  std::string sound_name_;
  std::optional<playback::ActuatorCalibration> calibration_;
  std::optional<playback::InverseFilter> filter_;
  std::unique_ptr<playback::PreparedEngine> engine_;
  std::unique_ptr<ContactFollower> follower_;
  std::unique_ptr<playback::AudioOutput> output_;
  FrameListener listener_;
};

}  // namespace nibrig::rig
