// AudioOutput refuses what the device cannot do with a message that names what was asked and
// what exists, on a real JACK server.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "playback/audio_output.hpp"
#include "playback/device_error.hpp"
#include "tests/playback/jack_stream_settings.hpp"
#include "tests/playback/signal_renderer.hpp"
#include "tests/support/jack_server.hpp"

namespace nibrig::playback {
namespace {

using ::testing::HasSubstr;

std::string open_error(const OutputSettings& settings) {
  testing::SignalRenderer renderer;
  try {
    AudioOutput output(renderer, settings);
  } catch (const DeviceError& e) {
    return e.what();
  }
  return "no error";
}

TEST(AudioOutputErrors, AMissingDeviceListsTheDevicesThatExist) {
  nibrig::testing::JackServer server;
  OutputSettings s = testing::jack_settings("errors");
  s.device = "Scarlett 2i2";
  const std::string message = open_error(s);
  EXPECT_THAT(message, HasSubstr("'Scarlett 2i2'"));
  EXPECT_THAT(message, HasSubstr("'system'"));
}

TEST(AudioOutputErrors, AnOutputChannelOutOfRangeSaysHowManyTheDeviceHas) {
  nibrig::testing::JackServer server;
  const std::string message = open_error(testing::jack_settings("errors", 3));
  EXPECT_THAT(message, HasSubstr("output channel 3 is out of range"));
  EXPECT_THAT(message, HasSubstr("has 2 output channels"));
}

TEST(AudioOutputErrors, AnInputChannelOutOfRangeSaysHowManyTheDeviceHas) {
  nibrig::testing::JackServer server;
  OutputSettings s = testing::jack_settings("errors");
  s.input_channel = 5;
  const std::string message = open_error(s);
  EXPECT_THAT(message, HasSubstr("input channel 5 is out of range"));
  EXPECT_THAT(message, HasSubstr("has 2 input channels"));
}

TEST(AudioOutputErrors, ARateOtherThanTheJackServersSaysWhichRateItRunsAt) {
  nibrig::testing::JackServer server;
  OutputSettings s = testing::jack_settings("errors");
  s.sample_rate = 44100;
  const std::string message = open_error(s);
  EXPECT_THAT(message, HasSubstr("does not support 44100 Hz"));
  EXPECT_THAT(message, HasSubstr("48000 Hz"));
  EXPECT_THAT(message, HasSubstr("JACK runs only at the rate its server was started with"));
}

TEST(AudioOutputErrors, NoJackServerIsSaidSo) {
  nibrig::testing::JackServer server;
  server.kill();
  const std::string message = open_error(testing::jack_settings("errors"));
  EXPECT_THAT(message, HasSubstr("'system'"));
  EXPECT_THAT(message, HasSubstr("no JACK server is running"));
}

TEST(AudioOutputErrors, ChannelZeroIsRejectedBeforeAnyDeviceIsTouched) {
  const std::string message = open_error(testing::jack_settings("errors", 0));
  EXPECT_THAT(message, HasSubstr("output channel 0 is out of range"));
}

}  // namespace
}  // namespace nibrig::playback
