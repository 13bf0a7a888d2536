#include "playback/audio_devices.hpp"

#include <rtaudio/RtAudio.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "playback/alsa_quiet.hpp"
#include "playback/device_error.hpp"
#include "playback/device_probe.hpp"
#include "playback/offline_render.hpp"

namespace nibrig::playback {
namespace {

std::string lower(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

std::string no_devices_reason(RtAudio::Api api) {
  switch (api) {
    case RtAudio::UNIX_JACK: {
      std::string reason = "no JACK server is running";
      if (const char* server = std::getenv("JACK_DEFAULT_SERVER"); server && *server) {
        reason += " (server name '" + std::string(server) + "' from JACK_DEFAULT_SERVER)";
      }
      return reason;
    }
    case RtAudio::LINUX_PULSE:
      return "no PulseAudio server answered";
    case RtAudio::LINUX_ALSA:
      return "no ALSA sound card was found";
    default:
      return "RtAudio found no devices";
  }
}

RtAudio::Api api_by_name(std::string_view name) {
  std::vector<RtAudio::Api> apis;
  RtAudio::getCompiledApi(apis);
  for (RtAudio::Api api : apis) {
    if (lower(RtAudio::getApiName(api)) == lower(name)) return api;
  }
  std::string known;
  for (const std::string& n : compiled_apis()) known += (known.empty() ? "" : ", ") + n;
  throw DeviceError("audio API '" + std::string(name) + "' is not compiled into RtAudio (" +
                    RtAudio::getVersion() + "); available: " + known);
}

ApiDevices probe(RtAudio::Api api) {
  ApiDevices result;
  result.api = RtAudio::getApiName(api);
  result.display_name = RtAudio::getApiDisplayName(api);
  try {
    quiet_alsa_library();
    RtAudio rt(api);
    // RtAudio would print its warnings to stderr; what matters is returned in the listing.
    rt.showWarnings(false);
    const DeviceTable table = probe_devices(rt);
    for (const ProbedDevice& d : table.devices) result.devices.push_back(d.info);
    if (table.count == 0) {
      result.unavailable_reason = no_devices_reason(api);
    } else if (result.devices.empty()) {
      result.unavailable_reason =
          "RtAudio could not probe any of its " + std::to_string(table.count) + " devices";
    }
  } catch (const RtAudioError& e) {
    // A server that goes away between counting and probing lands here: it is a state of the
    // system, not a failure of the listing.
    result.devices.clear();
    result.unavailable_reason = e.what();
  }
  result.available = !result.devices.empty();
  return result;
}

bool has_output(const DeviceInfo& d) { return d.output_channels > 0; }

}  // namespace

std::vector<std::string> compiled_apis() {
  std::vector<RtAudio::Api> apis;
  RtAudio::getCompiledApi(apis);
  std::vector<std::string> names;
  for (RtAudio::Api api : apis) names.push_back(RtAudio::getApiName(api));
  return names;
}

std::vector<ApiDevices> list_devices() {
  std::vector<RtAudio::Api> apis;
  RtAudio::getCompiledApi(apis);
  std::vector<ApiDevices> result;
  for (RtAudio::Api api : apis) result.push_back(probe(api));
  return result;
}

ApiDevices list_devices(std::string_view api) { return probe(api_by_name(api)); }

std::string describe_devices(const ApiDevices& api) {
  std::ostringstream out;
  out << api.api << ":";
  if (!api.available) {
    out << " unavailable (" << api.unavailable_reason << ")";
    return out.str();
  }
  for (const DeviceInfo& d : api.devices) {
    out << "\n  '" << d.name << "': " << d.output_channels << " out, " << d.input_channels
        << " in, rates";
    for (unsigned rate : d.sample_rates) out << ' ' << rate;
    out << " Hz";
    if (d.default_output) out << ", default output";
    if (d.default_input) out << ", default input";
  }
  return out.str();
}

const DeviceInfo& find_device(const std::vector<DeviceInfo>& devices, std::string_view name,
                              std::string_view api) {
  for (const DeviceInfo& d : devices) {
    if (d.name == name) return d;
  }
  const std::string wanted = lower(name);
  std::vector<const DeviceInfo*> matches;
  for (const DeviceInfo& d : devices) {
    if (lower(d.name).find(wanted) != std::string::npos) matches.push_back(&d);
  }
  if (matches.size() == 1) return *matches.front();

  std::string names;
  for (const DeviceInfo& d : devices) names += (names.empty() ? "'" : ", '") + d.name + "'";
  if (names.empty()) names = "none";
  if (matches.empty()) {
    throw DeviceError("no " + std::string(api) + " audio device matches '" + std::string(name) +
                      "'; devices: " + names);
  }
  std::string which;
  for (const DeviceInfo* d : matches) which += (which.empty() ? "'" : ", '") + d->name + "'";
  throw DeviceError("audio device name '" + std::string(name) + "' is ambiguous under " +
                    std::string(api) + ": it matches " + which +
                    "; give more of the name (devices: " + names + ")");
}

DeviceChoice choose_device(std::string_view api, std::string_view device) {
  std::vector<ApiDevices> candidates;
  if (api.empty()) {
    candidates = list_devices();
  } else {
    candidates.push_back(list_devices(api));
  }

  if (!device.empty()) {
    if (!api.empty()) {
      const ApiDevices& only = candidates.front();
      if (!only.available) {
        throw DeviceError("no " + only.api + " audio device matches '" + std::string(device) +
                          "': " + only.api + " is unavailable (" + only.unavailable_reason + ")");
      }
      return DeviceChoice{only.api, find_device(only.devices, device, only.api)};
    }
    // A device name without an API: the first API where it names exactly one device.
    for (const ApiDevices& a : candidates) {
      if (!a.available) continue;
      try {
        return DeviceChoice{a.api, find_device(a.devices, device, a.api)};
      } catch (const DeviceError&) {
      }
    }
  } else {
    for (const ApiDevices& a : candidates) {
      const auto is_default = [](const DeviceInfo& d) { return d.default_output && has_output(d); };
      auto it = std::find_if(a.devices.begin(), a.devices.end(), is_default);
      if (it == a.devices.end()) it = std::find_if(a.devices.begin(), a.devices.end(), has_output);
      if (it != a.devices.end()) return DeviceChoice{a.api, *it};
    }
  }

  std::string listing;
  for (const ApiDevices& a : candidates) listing += "\n" + describe_devices(a);
  const std::string asked = device.empty() ? "an output device" : "'" + std::string(device) + "'";
  const std::string where = api.empty() ? "any audio API" : std::string(api);
  throw DeviceError("no audio device found for " + asked + " under " + where + ":" + listing);
}

OutputSettings output_settings_for(std::string_view api, std::string_view device, unsigned rate,
                                   unsigned period_frames, unsigned output_channel, std::string stream_name) {
  if (rate != 0) check_render_rate(rate, "rate");
  check_render_block(period_frames, "period");
  if (output_channel < 1 || output_channel > kMostOutputChannels)
    throw std::invalid_argument("channel: " + std::to_string(output_channel) +
                                ": expected an output channel, 1 to " +
                                std::to_string(kMostOutputChannels));
  const DeviceChoice choice = choose_device(api, device);
  OutputSettings s;
  s.api = choice.api;
  s.device = choice.device.name;
  s.sample_rate = rate > 0 ? rate : choice.device.preferred_sample_rate > 0 ? choice.device.preferred_sample_rate : 48000;
  s.period_frames = period_frames;
  s.output_channel = output_channel;
  s.stream_name = std::move(stream_name);
  return s;
}

}  // namespace nibrig::playback
