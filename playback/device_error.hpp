// The one exception type of the audio-device layer: what was asked (API, device, rate, period,
// channel) and why it could not be had, in words a user can act on. Thrown only on control
// threads, never from an audio callback.
#pragma once

#include <stdexcept>
#include <string>

namespace nibrig::playback {

class DeviceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace nibrig::playback
