#include "ui/cli/device_options.hpp"

#include "playback/audio_devices.hpp"
#include "playback/offline_render.hpp"
#include "ui/options/number_checks.hpp"

namespace nibrig::ui::cli {

void add_device_options(CLI::App* cmd, DeviceOptions& o) {
  cmd->add_option("--api", o.api, "Audio API: jack, alsa or pulse (default: the first with a device)");
  cmd->add_option("--device", o.device,
                  "Device name, or a unique part of it (see `nibrig devices`; default: the API's default)");
  cmd->add_option("--channel", o.channel, "Output channel driving the actuator (1-based)")
      ->check(whole_in_range(1, playback::kMostOutputChannels, "a channel number"));
  // 0, the device's own rate, is the default only: typed, it would be a rate of nothing.
  cmd->add_option("--rate", o.rate, "Sample rate in Hz (default: the device's)")
      ->check(whole_in_range(static_cast<long long>(playback::kLowestRenderRateHz),
                             static_cast<long long>(playback::kHighestRenderRateHz),
                             "a sample rate in Hz"));
  cmd->add_option("--period", o.period, "Period in frames (JACK uses its server's)")
      ->check(whole_in_range(1, static_cast<long long>(playback::kLargestRenderBlock),
                             "a period in frames"));
}

playback::OutputSettings output_settings(const DeviceOptions& o, const std::string& stream_name) {
  return playback::output_settings_for(o.api, o.device, o.rate, o.period, o.channel, stream_name);
}

}  // namespace nibrig::ui::cli
