// The former names of PreparedEngine and of a voice given field by field, for the one caller that
// still uses them (the rig's actuator player in ui/cli/cmd_rig.cpp). Deleting this file leaves
// that caller to say `playback::PreparedEngine(settings, sound, stroke, seed)`.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "playback/prepared_engine.hpp"

namespace nibrig::playback {

struct SessionVoice {
  std::string name;
  const model::modal::ModalModel& modal;
  const model::io::VelocitySpectrum& spectrum;
};

class PlaybackSession : public PreparedEngine {
 public:
  PlaybackSession(rt::EngineSettings settings, const std::vector<SessionVoice>& voices,
                  std::unique_ptr<rt::StrokeSource> stroke, std::uint64_t seed)
      : PreparedEngine(settings, sources(voices), std::move(stroke), seed) {}

 private:
  static std::vector<model::modal::VoiceSource> sources(const std::vector<SessionVoice>& voices) {
    std::vector<model::modal::VoiceSource> made;
    for (const auto& v : voices) made.push_back({v.name, "", v.modal, v.spectrum});
    return made;
  }
};

}  // namespace nibrig::playback
