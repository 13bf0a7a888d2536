// Reads an RtAudio device table into DeviceInfo, with each device's RtAudio index. Shared by the
// listing and by AudioOutput, which turns a name into an index on the very RtAudio object that
// opens the stream, never storing an index.
#pragma once

#include <rtaudio/RtAudio.h>

#include <chrono>
#include <vector>

#include "playback/audio_devices.hpp"

namespace nibrig::playback {

struct ProbedDevice {
  unsigned index = 0;  // valid for the RtAudio object that was probed, and only now
  DeviceInfo info;
};

struct DeviceTable {
  unsigned count = 0;     // devices RtAudio reported
  unsigned unprobed = 0;  // of those, how many could not be probed even after retries
  std::vector<ProbedDevice> devices;
};

// May throw RtAudioError (a server vanishing mid-probe). An empty table and a device that fails
// to probe are retried a few times, 20 ms apart: RtAudio's JACK back end opens a temporary client
// to count and another per device, and a busy server refuses one now and then.
DeviceTable probe_devices(RtAudio& rt);

// The same patience for other calls that go through such temporary clients (openStream counts
// the devices again): how many tries, and the pause between them.
inline constexpr int kProbeAttempts = 3;
inline constexpr std::chrono::milliseconds kProbeRetryPause{20};

}  // namespace nibrig::playback
