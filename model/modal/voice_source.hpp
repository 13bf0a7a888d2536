// What a real-time voice is made of: a stylus's modes and the acceleration spectrum A(f, v) the
// sensor should see as the tip moves at speed v. The tool sounds (model/design/tool_sound.hpp)
// are made as this type and rt::build_voice and the players in playback/ take it as it is, so no
// layer copies it field by field into its own.
#pragma once

#include <string>

#include "model/io/velocity_spectrum.hpp"
#include "model/modal/modal_model.hpp"

namespace nibrig::model::modal {

struct VoiceSource {
  std::string name;   // "cryon on office", "predicted DM85:0.5,vero:0.5,tip=2mm on office"
  std::string modes;  // the design whose modes shape it
  ModalModel modal;
  io::VelocitySpectrum spectrum;
};

}  // namespace nibrig::model::modal
