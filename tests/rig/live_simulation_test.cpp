#include "rig/live_simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "model/design/tool_sound.hpp"
#include "rig/simulated_rig.hpp"
#include "tests/rig/bundled_sound.hpp"

namespace nibrig::rig {
namespace {

double rms(const std::vector<float>& x, std::size_t begin, std::size_t end) {
  double sum = 0.0;
  for (std::size_t i = begin; i < end; ++i) sum += static_cast<double>(x[i]) * x[i];
  return std::sqrt(sum / static_cast<double>(end - begin));
}

// Frames at rest, then sliding from frame 500 on: the simulation is silent while the tip rests and
// sounds within the first frame after it moves (the contact acts within one frame: 48 samples).
TEST(LiveSimulation, FollowsTheMeasuredContactWithinOneFrame) {
  LiveSimulation live(testing::bundled_sound("cryon", "office"), 48000.0, 1000.0, 1);
  std::vector<float> simulated;
  for (std::uint32_t k = 0; k < 1000; k += 10) {  // batches of 10 frames, as a rig delivers
    RigData batch;
    for (std::uint32_t j = k; j < k + 10; ++j) {
      SensorFrame f;
      f.sequence = j;
      f.speed_m_s = j < 500 ? 0.0f : 0.1f;
      f.normal_force_N = 2.2f;
      batch.frames.push_back(f);
    }
    batch.acceleration.assign(480, 0.0f);
    live.feed(batch, simulated);
  }
  ASSERT_EQ(simulated.size(), 48000u);
  EXPECT_EQ(live.samples(), 48000u);
  EXPECT_LT(rms(simulated, 0, 500 * 48), 1e-6);  // at rest: silence
  const double moving = rms(simulated, 600 * 48, 1000 * 48);
  EXPECT_GT(moving, 1e-3);  // cryon on office at 100 mm/s: a few hundredths of m/s²
  // Within the first frame after the step the tool already sounds at a good part of its level.
  EXPECT_GT(rms(simulated, 501 * 48, 503 * 48), 0.1 * moving);
}

// The simulated rig and the live simulation with one seed drive the same forcing noise, the rig by
// the motor's speed, the live simulation by the encoder's reading of it delivered frame by frame:
// their acceleration must line up sample for sample. The cross-correlation peaks at lag 0 (the
// streams are aligned to the sample) and is high (what differs is the encoder noise and the
// one-frame ramp of the live contact, plus the rig's sensor noise and motor line).
TEST(LiveSimulation, RunsSampleForSampleBesideASimulatedRigOfTheSameTool) {
  SimulatedRigSettings settings;
  settings.speedup = 0.0;
  settings.seed = 5;
  SimulatedRig rig(settings, testing::bundled_sound("cryon", "office"), "cryon", "office");
  rig.start(study_sweep_profile(3.0));
  LiveSimulation live(testing::bundled_sound("cryon", "office"), 48000.0, 1000.0, SimulatedRig::tool_seed(5));
  std::vector<float> measured, simulated;
  RigData batch;
  bool more = true;
  while (more) {
    batch.clear();
    more = rig.read(batch, std::chrono::milliseconds(100));
    for (float a : batch.acceleration) measured.push_back(static_cast<float>(a * settings.accelerometer_m_s2_per_unit));
    live.feed(batch, simulated);
  }
  ASSERT_EQ(simulated.size(), measured.size());
  const auto correlation = [&](long lag) {
    double xy = 0, xx = 0, yy = 0;
    for (std::size_t i = 48000; i + 48000 < measured.size(); ++i) {
      const double x = measured[i], y = simulated[static_cast<std::size_t>(static_cast<long>(i) + lag)];
      xy += x * y, xx += x * x, yy += y * y;
    }
    return xy / std::sqrt(xx * yy);
  };
  long best = 0;
  double best_r = -1.0;
  for (long lag = -96; lag <= 96; ++lag) {
    const double r = correlation(lag);
    if (r > best_r) best_r = r, best = lag;
  }
  EXPECT_EQ(best, 0);
  RecordProperty("correlation", std::to_string(best_r));
  EXPECT_GT(best_r, 0.9);
}

}  // namespace
}  // namespace nibrig::rig
