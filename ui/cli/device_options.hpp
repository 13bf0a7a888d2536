// The options that name an audio device (audition, calibrate): API and device by name, never by
// index, the output channel, and the sample rate, which defaults to the device's own.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "playback/audio_output.hpp"

namespace nibrig::ui::cli {

struct DeviceOptions {
  std::string api, device;
  unsigned channel = 1;
  unsigned rate = 0;    // 0 = the device's preferred rate (JACK: the server's)
  unsigned period = 64;
};

void add_device_options(CLI::App* cmd, DeviceOptions& o);

// The device chosen, its rate settled, as AudioOutput settings (throws playback::DeviceError).
playback::OutputSettings output_settings(const DeviceOptions& o, const std::string& stream_name);

}  // namespace nibrig::ui::cli
