// Which audio back ends (RtAudio APIs) and devices exist, and the choice of one by name. Devices
// are chosen by API and device name, never by index: indices change when a server restarts or a
// device is plugged in, names do not.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "playback/audio_output.hpp"

namespace nibrig::playback {

struct DeviceInfo {
  std::string name;
  unsigned output_channels = 0;
  unsigned input_channels = 0;
  std::vector<unsigned> sample_rates;  // Hz; under JACK only the server's rate
  unsigned preferred_sample_rate = 0;  // Hz; 0 when the back end does not say
  bool default_output = false;
  bool default_input = false;
};

struct ApiDevices {
  std::string api;           // short name, as `choose_device` accepts it: "jack", "alsa", "pulse"
  std::string display_name;  // RtAudio's name for people: "Jack", "ALSA", "Pulse"
  bool available = false;    // false: no server or no device; `unavailable_reason` says which
  std::string unavailable_reason;
  std::vector<DeviceInfo> devices;
};

struct DeviceChoice {
  std::string api;  // short name
  DeviceInfo device;
};

// Short names of the APIs compiled into RtAudio, in RtAudio's own order of preference.
std::vector<std::string> compiled_apis();

// Every compiled API with its devices. An API without a server or devices is listed as
// unavailable with the reason; this never throws for a missing server.
std::vector<ApiDevices> list_devices();

// One API by name (case-insensitive). Throws DeviceError when the API is not compiled in.
ApiDevices list_devices(std::string_view api);

// The device to open. Empty `api`: the first API (in RtAudio's order) that has an output device.
// Empty `device`: that API's default output device, else its first device with outputs. A device
// name matches exactly first, else as a unique case-insensitive substring. Throws DeviceError
// naming what was asked and listing the devices that exist when nothing or more than one matches.
DeviceChoice choose_device(std::string_view api, std::string_view device);

// The matching rule of `choose_device` on a given list (exact, else unique case-insensitive
// substring). `api` only words the error. Throws DeviceError.
const DeviceInfo& find_device(const std::vector<DeviceInfo>& devices, std::string_view name,
                              std::string_view api);

// The most channels a device is taken to have, out or in: a channel beyond is a typo.
inline constexpr unsigned kMostOutputChannels = 1024;

// The settings to open a device asked for by API and name (chosen as choose_device does) at
// `rate` Hz, or at the device's own rate when 0 (JACK: the server's; 48 kHz when it does not say).
// Every face opens its devices through this, so its ranges are checked here once: `rate` 0 or a
// render's (kLowestRenderRateHz to kHighestRenderRateHz), `period_frames` a render block's,
// `output_channel` 1 to kMostOutputChannels; std::invalid_argument named "rate", "period",
// "channel" otherwise. Throws DeviceError when no device matches.
OutputSettings output_settings_for(std::string_view api, std::string_view device, unsigned rate,
                                   unsigned period_frames, unsigned output_channel, std::string stream_name);

// One line per device ("system: 2 out, 2 in, 48000 Hz, default output"), for errors and the CLI.
std::string describe_devices(const ApiDevices& api);

}  // namespace nibrig::playback
