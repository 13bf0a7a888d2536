// The simulated tool on the actuator while the simulated rig runs a profile in real time, through a
// real JACK server: an independent libjack client records what the actuator receives, and its level
// in each step of the profile is the level the same engine renders offline at that step's speed.
#include "rig/actuator_player.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>
#include <vector>

#include "playback/prepared_engine.hpp"
#include "rig/simulated_rig.hpp"
#include "rig/speed_profile.hpp"
#include "rt/stroke_source.hpp"
#include "tests/playback/jack_recorder.hpp"
#include "tests/rig/bundled_sound.hpp"
#include "tests/support/jack_server.hpp"

namespace nibrig::rig {
namespace {

constexpr double kPlayerRateHz = 48000.0;  // the test server's and the engine's
constexpr const char* kPlayerPort = "actuator-under-test:outport 0";

struct PlayerStep {
  double from_s, to_s, speed_m_s;
};
// Three steps, long enough that a window well inside each (after the motor settled, away from the
// next step) holds most of a second: slow, fast, then back to medium, so that following is shown
// both ways.
constexpr PlayerStep kPlayerSteps[] = {{0.0, 1.5, 0.03}, {1.5, 3.0, 0.2}, {3.0, 4.5, 0.06}};
constexpr double kPlayerWindowAfterStepS = 0.4, kPlayerWindowBeforeNextS = 0.2;

double player_rms(const float* x, std::size_t n) {
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) sum += static_cast<double>(x[i]) * x[i];
  return std::sqrt(sum / static_cast<double>(n));
}

// The level the player's engine makes at a constant speed and the rig's load, rendered offline over
// the window a step is measured in.
double offline_player_rms(const model::design::ToolSound& sound, double speed_m_s, double load_N) {
  rt::EngineSettings settings;
  settings.sample_rate_hz = kPlayerRateHz;
  settings.slots = 1;
  playback::PreparedEngine session(settings, sound,
                                   std::make_unique<rt::ConstantStroke>(speed_m_s, load_N), 11);
  const auto total = static_cast<std::size_t>(1.5 * kPlayerRateHz);
  std::vector<float> out(total);
  for (std::size_t at = 0; at < total; at += 64) session.engine().render(out.data() + at, std::min<std::size_t>(64, total - at));
  const auto from = static_cast<std::size_t>(kPlayerWindowAfterStepS * kPlayerRateHz);
  const auto to = total - static_cast<std::size_t>(kPlayerWindowBeforeNextS * kPlayerRateHz);
  return player_rms(out.data() + from, to - from);
}

double player_db(double ratio) { return 20.0 * std::log10(ratio); }

TEST(ActuatorPlayer, TheActuatorFollowsTheSimulatedRigsSpeedThroughJack) {
  nibrig::testing::JackServer server;
  const model::design::ToolSound& sound = testing::bundled_sound("cryon", "office");
  SimulatedRigSettings rig_settings;
  rig_settings.speedup = 1.0;  // real time: the actuator follows as it would a turntable
  rig_settings.seed = 5;
  SimulatedRig rig(rig_settings, sound, "cryon", "office");
  std::vector<ProfilePoint> points;
  for (const PlayerStep& s : kPlayerSteps) points.push_back({s.from_s, s.speed_m_s}), points.push_back({s.to_s, s.speed_m_s});
  const SpeedProfile profile("three steps", points);

  ActuatorPlayerSettings settings;
  settings.device.api = "jack";
  settings.device.stream_name = "actuator-under-test";
  settings.seed = 3;
  ActuatorPlayer player(rig, sound, settings);
  EXPECT_FALSE(player.playing());
  EXPECT_FALSE(player.stream_info().has_value());
  player.play();
  ASSERT_TRUE(player.playing());
  EXPECT_EQ(player.stream_info()->api, "jack");

  const double pre_roll_s = 0.3;  // the engine at rest before the turntable moves: silence
  const auto capacity = static_cast<std::size_t>((pre_roll_s + profile.duration_s() + 1.0) * kPlayerRateHz);
  playback::testing::JackRecorder ear("ear", 1, capacity);
  ASSERT_TRUE(ear.connect(kPlayerPort, 0));
  ear.start();
  const auto recording_from = std::chrono::steady_clock::now();
  std::this_thread::sleep_for(std::chrono::duration<double>(pre_roll_s));
  const auto rig_from = std::chrono::steady_clock::now();
  rig.start(profile);
  RigData batch;
  while (rig.read(batch, std::chrono::milliseconds(100))) batch.clear();
  ASSERT_TRUE(ear.wait_full(std::chrono::seconds(20))) << ear.recorded() << " of " << capacity << " recorded";

  // The rig tells the player its newest frame per read, each a few milliseconds of frames: over
  // 4.5 s there are hundreds, every one applied within a block or superseded by the next.
  const FollowLatency latency = player.latency();
  EXPECT_GT(latency.contacts, 200u);

  const std::vector<float>& heard = ear.samples(0);
  // Where the profile starts in the recording: within a JACK period and a read of the rig's start,
  // a few milliseconds against windows that keep 0.2 s or more from every step.
  const double offset_s = std::chrono::duration<double>(rig_from - recording_from).count();
  EXPECT_LT(player_rms(heard.data(), static_cast<std::size_t>(0.8 * offset_s * kPlayerRateHz)), 1e-6);
  std::vector<double> measured, expected;
  for (const PlayerStep& s : kPlayerSteps) {
    const auto from = static_cast<std::size_t>((offset_s + s.from_s + kPlayerWindowAfterStepS) * kPlayerRateHz);
    const auto to = static_cast<std::size_t>((offset_s + s.to_s - kPlayerWindowBeforeNextS) * kPlayerRateHz);
    measured.push_back(player_rms(heard.data() + from, to - from));
    expected.push_back(offline_player_rms(sound, s.speed_m_s, rig_settings.normal_load_N));
  }
  // 2 dB: the forcing is noise, seeded otherwise offline, over a window of most of a second, and
  // the rig adds its motor's settling and its encoder and force noise (0.3 mm/s, 5 mN rms); the
  // steps heard came within 0.8 dB of the offline level, run after run.
  constexpr double kPlayerToleranceDb = 2.0;
  for (std::size_t i = 0; i < measured.size(); ++i)
    EXPECT_NEAR(player_db(measured[i] / expected[i]), 0.0, kPlayerToleranceDb)
        << "step " << i << " at " << kPlayerSteps[i].speed_m_s * 1e3 << " mm/s: heard " << measured[i]
        << ", offline " << expected[i];
  // The steps lie further apart than twice the tolerance (10 and 7.5 dB from the fast one), so an
  // actuator that kept any other step's speed, or lagged a step behind, fails above.
  EXPECT_GT(player_db(expected[1] / expected[0]), 2.0 * kPlayerToleranceDb);
  EXPECT_GT(player_db(expected[1] / expected[2]), 2.0 * kPlayerToleranceDb);

  // Turned off, the actuator's port goes; turned on again, it comes back.
  player.stop();
  EXPECT_FALSE(player.playing());
  EXPECT_EQ(jack_port_by_name(ear.client(), kPlayerPort), nullptr);
  player.play();
  EXPECT_NE(jack_port_by_name(ear.client(), kPlayerPort), nullptr);
}

}  // namespace
}  // namespace nibrig::rig
