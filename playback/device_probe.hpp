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

// How long to wait for a busy server. A listing asks whether devices are there (no server is an
// answer, given within 60 ms); opening a device a person named asks that it be opened, and a
// loaded server that refuses its temporary clients for a few hundred milliseconds (seen in CI) is
// waited for, up to 0.6 s.
enum class ProbePatience { listing, opening };

// May throw RtAudioError (a server vanishing mid-probe). An empty table and a device that fails
// to probe are retried: RtAudio's JACK back end opens a temporary client to count and another per
// device, and a busy server refuses one now and then.
DeviceTable probe_devices(RtAudio& rt, ProbePatience patience = ProbePatience::listing);

// The tries, and the pause before try k (k >= 1, doubling from 20 ms), for such temporary clients
// (openStream counts the devices again).
int probe_attempts(ProbePatience patience);
std::chrono::milliseconds probe_retry_pause(int attempt);

}  // namespace nibrig::playback
