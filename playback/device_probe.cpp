#include "playback/device_probe.hpp"

#include <chrono>
#include <thread>

namespace nibrig::playback {
namespace {

constexpr int kAttempts = kProbeAttempts;
constexpr std::chrono::milliseconds kRetryPause = kProbeRetryPause;

}  // namespace

DeviceTable probe_devices(RtAudio& rt) {
  DeviceTable table;
  // RtAudio's JACK back end counts devices through a temporary client, and reports 0 when that
  // client cannot be opened: a running but busy server can refuse one now and then.
  table.count = rt.getDeviceCount();
  for (int attempt = 1; attempt < kAttempts && table.count == 0; ++attempt) {
    std::this_thread::sleep_for(kRetryPause);
    table.count = rt.getDeviceCount();
  }
  for (unsigned i = 0; i < table.count; ++i) {
    RtAudio::DeviceInfo d;
    for (int attempt = 0; attempt < kAttempts; ++attempt) {
      if (attempt > 0) std::this_thread::sleep_for(kRetryPause);
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
