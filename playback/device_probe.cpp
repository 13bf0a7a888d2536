#include "playback/device_probe.hpp"

#include <algorithm>
#include <chrono>
#include <thread>

namespace nibrig::playback {

int probe_attempts(ProbePatience patience) { return patience == ProbePatience::listing ? 3 : 6; }

std::chrono::milliseconds probe_retry_pause(int attempt) {
  return std::chrono::milliseconds(20) * (1 << std::min(attempt - 1, 8));
}

DeviceTable probe_devices(RtAudio& rt, ProbePatience patience) {
  const int attempts = probe_attempts(patience);
  DeviceTable table;
  // RtAudio's JACK back end counts devices through a temporary client, and reports 0 when that
  // client cannot be opened: a running but busy server can refuse one now and then.
  table.count = rt.getDeviceCount();
  for (int attempt = 1; attempt < attempts && table.count == 0; ++attempt) {
    std::this_thread::sleep_for(probe_retry_pause(attempt));
    table.count = rt.getDeviceCount();
  }
  for (unsigned i = 0; i < table.count; ++i) {
    RtAudio::DeviceInfo d;
    for (int attempt = 0; attempt < attempts; ++attempt) {
      if (attempt > 0) std::this_thread::sleep_for(probe_retry_pause(attempt));
      d = rt.getDeviceInfo(i);
      if (d.probed) break;
    }
    if (!d.probed) {
      ++table.unprobed;
      continue;
    }
    table.devices.push_back(
        ProbedDevice{i, DeviceInfo{d.name, d.outputChannels, d.inputChannels, d.sampleRates,
                                   d.preferredSampleRate, d.isDefaultOutput, d.isDefaultInput}});
  }
  return table;
}

}  // namespace nibrig::playback
