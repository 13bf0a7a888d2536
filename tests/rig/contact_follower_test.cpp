#include "rig/contact_follower.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <vector>

#include "model/design/tool_sound.hpp"
#include "playback/prepared_engine.hpp"
#include "rt/stroke_source.hpp"
#include "tests/rig/bundled_sound.hpp"
#include "tests/support/allocation_counter.hpp"

namespace nibrig::rig {
namespace {

std::unique_ptr<playback::PreparedEngine> cryon_session() {
  const model::design::ToolSound& sound = testing::bundled_sound("cryon", "office");
  rt::EngineSettings settings;
  settings.slots = 1;
  return std::make_unique<playback::PreparedEngine>(
      settings, sound, std::make_unique<rt::ConstantStroke>(0.0, 0.0), 1);
}

double rms(const std::vector<float>& x) {
  double sum = 0.0;
  for (float v : x) sum += static_cast<double>(v) * v;
  return std::sqrt(sum / static_cast<double>(x.size()));
}

// The engine plays what the frames say (silent at rest, sounding when sliding), and the block that
// takes a frame notes how long it waited since the frame arrived — here a frame stamped as arrived
// 5 ms ago.
TEST(ContactFollower, TheEngineFollowsTheFramesAndTheWaitIsMeasured) {
  auto session = cryon_session();
  ContactFollower follower(session->engine());
  std::vector<float> block(64);
  SensorFrame rest;
  rest.normal_force_N = 2.2f;
  follower.follow(rest);
  for (int i = 0; i < 50; ++i) follower.render(block.data(), block.size());
  EXPECT_LT(rms(block), 1e-6);

  SensorFrame sliding = rest;
  sliding.speed_m_s = 0.1f;
  sliding.host_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(
                        (std::chrono::steady_clock::now() - std::chrono::milliseconds(5)).time_since_epoch())
                        .count();
  follower.follow(sliding);
  follower.render(block.data(), block.size());
  const FollowLatency latency = follower.latency();
  EXPECT_EQ(latency.contacts, 2u);
  EXPECT_GE(latency.max_s, 0.005);
  EXPECT_LT(latency.max_s, 0.5);  // 5 ms and a render, not a stale stamp
  for (int i = 0; i < 50; ++i) follower.render(block.data(), block.size());
  EXPECT_GT(rms(block), 1e-4);
}

// The follower's render is the audio callback's: it allocates nothing, posts or none.
TEST(ContactFollower, RenderAllocatesNothing) {
  auto session = cryon_session();
  ContactFollower follower(session->engine());
  std::vector<float> block(64);
  SensorFrame frame;
  frame.normal_force_N = 2.2f;
  frame.speed_m_s = 0.05f;
  follower.follow(frame);
  follower.render(block.data(), block.size());  // the engine's first block sets itself up
  session->engine().collect();
  std::size_t during = 0;
  for (int i = 0; i < 2000; ++i) {
    frame.speed_m_s = 0.05f + 0.0001f * static_cast<float>(i % 100);
    follower.follow(frame);  // the control side may run anywhere; only render is counted
    const std::size_t before = nibrig::testing::allocations_on_this_thread();
    follower.render(block.data(), block.size());
    during += nibrig::testing::allocations_on_this_thread() - before;
    if (i % 64 == 0) session->engine().collect();
  }
  EXPECT_EQ(during, 0u);
  EXPECT_EQ(follower.latency().contacts, 2001u);
}

}  // namespace
}  // namespace nibrig::rig
