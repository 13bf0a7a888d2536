// The panel's player on a real JACK server: silent until a tool is loaded and moved, the tool's
// signal once it is, the other slot's on a switch, and silence again when the contact stops; with
// no device at all every command still goes through (the engine is drained by the caller).
#include "playback/live_audition.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <numeric>
#include <thread>

#include "tests/playback/jack_recorder.hpp"
#include "tests/playback/jack_stream_settings.hpp"
#include "tests/rt/test_voices.hpp"
#include "tests/support/jack_server.hpp"

namespace nibrig::playback {
namespace {

using namespace std::chrono_literals;

using rt::testing::small_stylus;

const model::io::VelocitySpectrum& cryon_on_note() {
  static const auto spectrum = rt::testing::catalog_spectrum("cryon", "note");
  return spectrum;
}

// The same tool four times as strong: slot 1 then plays 12 dB louder, which tells a switch apart
// from two tools whose levels happen to be close.
model::io::VelocitySpectrum four_times(model::io::VelocitySpectrum s) {
  for (auto& row : s.amplitude_m_s2)
    for (double& a : row) a *= 4.0;
  return s;
}

double rms_of_last(const std::vector<float>& samples, std::size_t end, std::size_t count) {
  double sum = 0.0;
  for (std::size_t i = end - count; i < end; ++i) sum += double(samples[i]) * samples[i];
  return std::sqrt(sum / static_cast<double>(count));
}

// Records `frames` of the audition's output with an independent libjack client.
std::vector<float> record(const std::string& port, std::size_t frames) {
  testing::JackRecorder ear("ear", 1, frames);
  EXPECT_TRUE(ear.connect(port, 0));
  ear.start();
  EXPECT_TRUE(ear.wait_full(20s)) << "recorded " << ear.recorded() << " frames";
  return ear.samples(0);
}

TEST(LiveAudition, PlaysTheLoadedToolSwitchesSlotsAndFallsSilentWhenTheContactStops) {
  nibrig::testing::JackServer server;
  LiveAudition audition(rt::EngineSettings{});
  audition.open(testing::jack_settings("audition"));
  ASSERT_TRUE(audition.playing_on_a_device());
  EXPECT_EQ(audition.stream_info()->api, "jack");

  // Nothing loaded: exact silence (the engine's output stage adds nothing of its own).
  const auto before = record("audition:outport 0", 9600);
  EXPECT_EQ(rms_of_last(before, before.size(), before.size()), 0.0);

  audition.load(0, {"cryon", "small stylus", small_stylus(), cryon_on_note()}, 7);
  const auto louder = four_times(cryon_on_note());
  audition.load(1, {"cryon x4", "small stylus", small_stylus(), louder}, 8);
  audition.set_contact(0.1, 2.2);
  EXPECT_EQ(audition.names()[0], "cryon");
  const auto cryon = record("audition:outport 0", 72000);
  // At 100 mm/s the crayon's vibration is well above the output stage's noise floor (a
  // sensor-acceleration of about 1 m/s² at the default gain of 0.05 per m/s²).
  const double cryon_rms = rms_of_last(cryon, cryon.size(), 48000);
  EXPECT_GT(cryon_rms, 1e-3);

  audition.select(1);
  EXPECT_EQ(audition.selected(), 1u);
  const auto loud = record("audition:outport 0", 72000);
  const double loud_rms = rms_of_last(loud, loud.size(), 48000);
  // 12 dB. A second of this noise's RMS scatters by about 0.3 dB from one second to the next (the
  // ratio came out at 11.7-12.8 dB for eight pairs of seeds; quarter-seconds had scattered by 2);
  // ±1.5 dB still tells a switch from a slot that did not change.
  EXPECT_NEAR(20 * std::log10(loud_rms / cryon_rms), 12.04, 1.5) << "cryon " << cryon_rms << ", x4 " << loud_rms;

  audition.set_contact(0.0, 0.0);
  const auto stopped = record("audition:outport 0", 24000);
  EXPECT_LT(rms_of_last(stopped, stopped.size(), 12000), cryon_rms * 1e-2);
  EXPECT_EQ(audition.output_stats()->losses, 0u);
}

// The proof that a control thread never waits for the audio thread: with the server dead, no
// callback drains the engine's queue, and a thousand commands still return at once; what the queue
// could not take is held, in order, and handed over once the device is back.
TEST(LiveAudition, ACommandNeverWaitsForTheAudioThread) {
  nibrig::testing::JackServer server;
  LiveAudition audition(rt::EngineSettings{});
  playback::OutputSettings settings = testing::jack_settings("held");
  settings.retry_interval = std::chrono::milliseconds(100);
  audition.open(settings);
  server.kill();
  const auto lost_by = std::chrono::steady_clock::now() + 20s;
  while (audition.output_status() != OutputStatus::lost && std::chrono::steady_clock::now() < lost_by)
    std::this_thread::sleep_for(10ms);
  ASSERT_EQ(audition.output_status(), OutputStatus::lost);
  for (int i = 0; i < 1000; ++i) audition.set_contact(0.05, 2.2);
  audition.load(1, {"cryon", "small stylus", small_stylus(), cryon_on_note()}, 1);
  for (int i = 0; i < 500; ++i) audition.select(i % 2);
  const std::size_t held = audition.pump();
  EXPECT_GT(held, 0u);  // the queue (256 commands) filled; the rest waits here
  EXPECT_EQ(audition.names()[1], "cryon");
  server.start();
  const auto back_by = std::chrono::steady_clock::now() + 30s;
  while (audition.pump() > 0 && std::chrono::steady_clock::now() < back_by) std::this_thread::sleep_for(10ms);
  EXPECT_EQ(audition.pump(), 0u);
  EXPECT_GE(audition.output_stats()->reconnects, 1u);
}

TEST(LiveAudition, WithoutADeviceEveryCommandStillGoesThrough) {
  LiveAudition audition(rt::EngineSettings{});
  EXPECT_FALSE(audition.playing_on_a_device());
  EXPECT_FALSE(audition.output_stats().has_value());
  // More commands than the engine's queue holds: each is drained by the caller.
  for (int i = 0; i < 600; ++i) audition.set_contact(0.05 + 1e-4 * i, 2.2);
  audition.load(2, {"cryon", "small stylus", small_stylus(), cryon_on_note()}, 1);
  audition.select(2);
  EXPECT_EQ(audition.selected(), 2u);
  EXPECT_EQ(audition.names()[2], "cryon");
  EXPECT_THROW(audition.select(3), std::invalid_argument);
  EXPECT_THROW(audition.load(3, {"cryon", "small stylus", small_stylus(), cryon_on_note()}, 1),
               std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::playback
