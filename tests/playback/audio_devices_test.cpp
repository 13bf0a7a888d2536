// Device listing and choice by name against a real JACK server (dummy driver): RtAudio sees the
// server's `system` client as one device, and bare libjack clients as further devices.
#include "playback/audio_devices.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "playback/device_error.hpp"
#include "tests/playback/jack_recorder.hpp"
#include "tests/support/jack_server.hpp"

namespace nibrig::playback {
namespace {

using ::testing::HasSubstr;
using testing::JackRecorder;

const ApiDevices* find_api(const std::vector<ApiDevices>& apis, const std::string& name) {
  const auto it =
      std::find_if(apis.begin(), apis.end(), [&](const ApiDevices& a) { return a.api == name; });
  return it == apis.end() ? nullptr : &*it;
}

std::string error_of(std::string_view api, std::string_view device) {
  try {
    choose_device(api, device);
  } catch (const DeviceError& e) {
    return e.what();
  }
  return "no error";
}

TEST(AudioDevices, ListsTheJackSystemDeviceWithItsChannelsAndTheServerRate) {
  nibrig::testing::JackServer server;
  const std::vector<ApiDevices> apis = list_devices();
  const ApiDevices* jack = find_api(apis, "jack");
  ASSERT_NE(jack, nullptr) << "RtAudio was built without JACK";
  ASSERT_TRUE(jack->available) << jack->unavailable_reason;
  ASSERT_EQ(jack->devices.size(), 1u) << describe_devices(*jack);
  const DeviceInfo& system = jack->devices.front();
  EXPECT_EQ(system.name, "system");
  // The dummy driver has 2 capture and 2 playback ports (jackd's defaults).
  EXPECT_EQ(system.output_channels, 2u);
  EXPECT_EQ(system.input_channels, 2u);
  EXPECT_EQ(system.sample_rates, std::vector<unsigned>{48000});
  EXPECT_TRUE(system.default_output);
  // The other compiled APIs are listed too, whether or not they have devices here.
  EXPECT_NE(find_api(apis, "alsa"), nullptr);
  EXPECT_NE(find_api(apis, "pulse"), nullptr);
}

TEST(AudioDevices, AnApiWithoutServerIsListedAsUnavailableWithTheReason) {
  nibrig::testing::JackServer server;
  server.kill();
  const ApiDevices jack = list_devices("jack");
  EXPECT_FALSE(jack.available);
  EXPECT_TRUE(jack.devices.empty());
  EXPECT_THAT(jack.unavailable_reason, HasSubstr("no JACK server is running"));
  EXPECT_THAT(jack.unavailable_reason, HasSubstr(server.name()));
}

TEST(AudioDevices, ChoosesByApiAndExactNameOrUniqueSubstringInAnyCase) {
  nibrig::testing::JackServer server;
  const DeviceChoice exact = choose_device("JACK", "system");
  EXPECT_EQ(exact.api, "jack");
  EXPECT_EQ(exact.device.name, "system");
  const DeviceChoice part = choose_device("jack", "SYS");
  EXPECT_EQ(part.device.name, "system");
  // No API and no device: JACK comes first in RtAudio's order and has an output device here.
  const DeviceChoice fallback = choose_device("", "");
  EXPECT_EQ(fallback.api, "jack");
  EXPECT_EQ(fallback.device.name, "system");
}

TEST(AudioDevices, AMissingDeviceNamesWhatWasAskedAndListsWhatExists) {
  nibrig::testing::JackServer server;
  const std::string message = error_of("jack", "Focusrite");
  EXPECT_THAT(message, HasSubstr("'Focusrite'"));
  EXPECT_THAT(message, HasSubstr("'system'"));
}

TEST(AudioDevices, AnAmbiguousNameListsTheMatchesAndAnExactNameStillWins) {
  nibrig::testing::JackServer server;
  // Each bare client with input ports is a device with outputs for RtAudio.
  JackRecorder a("probe-a", 1, 64);
  JackRecorder b("probe-b", 1, 64);
  const std::string message = error_of("jack", "PROBE");
  EXPECT_THAT(message, HasSubstr("ambiguous"));
  EXPECT_THAT(message, HasSubstr("'probe-a'"));
  EXPECT_THAT(message, HasSubstr("'probe-b'"));
  EXPECT_EQ(choose_device("jack", "probe-b").device.name, "probe-b");
  EXPECT_EQ(choose_device("jack", "probe-b").device.output_channels, 1u);
}

TEST(AudioDevices, AnUnknownApiListsTheCompiledOnes) {
  const std::string message = error_of("coreaudio", "");
  EXPECT_THAT(message, HasSubstr("'coreaudio'"));
  EXPECT_THAT(message, HasSubstr("jack"));
  EXPECT_THAT(message, HasSubstr("alsa"));
}

// Every face opens its device through output_settings_for, so its ranges are refused there, named
// as a Python call names them, before any device is looked for (none exists under this API).
TEST(AudioDevices, OutputSettingsRefuseARateAPeriodAndAChannelOutOfRangeByName) {
  const auto refused = [](unsigned rate, unsigned period, unsigned channel) {
    try {
      output_settings_for("no-such-api", "", rate, period, channel, "nibrig-test");
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    } catch (const DeviceError&) {
      return std::string("device looked for");
    }
    return std::string("taken");
  };
  EXPECT_THAT(refused(100, 256, 1), ::testing::StartsWith("rate: 100"));
  EXPECT_THAT(refused(0, 0, 1), ::testing::StartsWith("period: 0"));
  EXPECT_THAT(refused(48000, 256, 0), ::testing::StartsWith("channel: 0"));
  EXPECT_THAT(refused(48000, 256, kMostOutputChannels + 1),
              ::testing::StartsWith("channel: " + std::to_string(kMostOutputChannels + 1)));
  // In range, the device is looked for (0: the device's own rate).
  EXPECT_EQ(refused(0, 256, 1), "device looked for");
}

}  // namespace
}  // namespace nibrig::playback
