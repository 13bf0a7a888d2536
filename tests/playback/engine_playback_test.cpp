// The acceptance test of the real-time path on a real JACK server (dummy driver, 48 kHz, 64-frame
// periods): the engine's output recorded back through a JACK connection equals its offline render
// one period later. The minute under a flood of updates is soak/engine_soak_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include "playback/audio_output.hpp"
#include "rt/engine.hpp"
#include "tests/playback/jack_recorder.hpp"
#include "tests/playback/jack_stream_settings.hpp"
#include "tests/playback/wait_until.hpp"
#include "tests/rt/test_voices.hpp"
#include "tests/support/jack_server.hpp"

namespace nibrig::playback {
namespace {

using namespace std::chrono_literals;

std::unique_ptr<rt::Engine> sweeping_engine() {
  auto engine = std::make_unique<rt::Engine>(rt::EngineSettings{});
  engine->load(0, rt::testing::catalog_voice("cryon", "note", engine->internal_rate(), 7));
  engine->select(0);
  engine->attach(std::make_unique<rt::SweepStroke>());
  return engine;
}

TEST(EnginePlayback, WhatItPlaysComesBackAsTheOfflineRenderOnePeriodLater) {
  nibrig::testing::JackServer server;
  auto engine = sweeping_engine();
  OutputSettings settings = testing::jack_settings("engine-loop");
  settings.input_channel = 1;
  AudioOutput output(*engine, settings);
  testing::JackRecorder patch("patch", 0, 0);
  ASSERT_TRUE(patch.connect_ports("engine-loop:outport 0", "engine-loop:inport 0"));

  std::vector<float> captured, block(4096);
  const auto drained = testing::wait_until(
      [&] {
        const std::size_t n = output.read_captured(block.data(), block.size());
        captured.insert(captured.end(), block.begin(), block.begin() + n);
        return captured.size() >= 72000;  // 1.5 s: half a sweep
      },
      20s);
  ASSERT_GE(drained.count(), 0.0) << "captured " << captured.size() << " samples";

  // The same inputs offline: a second engine, same voice and seed, the same 64-frame blocks.
  auto reference = sweeping_engine();
  std::vector<float> offline(captured.size());
  for (std::size_t at = 0; at < offline.size(); at += 64)
    reference->render(offline.data() + at, std::min<std::size_t>(64, offline.size() - at));

  const std::size_t probe = captured.size() - 1024;
  const auto found = testing::locate(offline, captured.data() + probe, 512);
  ASSERT_TRUE(found.has_value()) << "the played samples are not in the offline render";
  const long delay = static_cast<long>(probe) - static_cast<long>(*found);
  // RtAudio's JACK back end hands the callback the input of the cycle before: one period is the
  // floor (recipes.md), and the measured delay is exactly that.
  EXPECT_EQ(delay, 64);
  std::printf("measured loopback delay: %ld frames (%.3f ms)\n", delay, delay / 48.0);
  // The patch is connected after the stream started: the capture is silent until then.
  const auto first_sound = static_cast<std::size_t>(
      std::find_if(captured.begin(), captured.end(), [](float x) { return x != 0.0f; }) -
      captured.begin());
  ASSERT_LT(first_sound, 24000u) << "the loop stayed silent for half a second";
  double max_error = 0;
  for (std::size_t j = std::max<std::size_t>(first_sound, delay); j < captured.size(); ++j)
    max_error = std::max(max_error, std::abs(double{captured[j]} - double{offline[j - delay]}));
  // Floats copied through JACK untouched: equal; 1e-6 allows for nothing but a float rounding.
  EXPECT_LE(max_error, 1e-6);
  EXPECT_EQ(output.stats().capture_dropped, 0u);
}

}  // namespace
}  // namespace nibrig::playback
