// The rig's budgets: a 10-minute capture at 1 kHz force and 48 kHz acceleration that
// drops nothing, and from a speed frame to the actuator's engine taking it within one audio period
// + 1 ms.
#include <benchmark/benchmark.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <thread>

#include "model/design/tool_sound.hpp"
#include "playback/audio_output.hpp"
#include "playback/prepared_engine.hpp"
#include "rig/capture.hpp"
#include "rig/contact_follower.hpp"
#include "rig/simulated_rig.hpp"
#include "rt/stroke_source.hpp"
#include "tests/support/jack_server.hpp"

namespace {

using namespace nibrig;

const model::design::ToolSound& cryon_office() {
  static const model::design::ToolSound sound = [] {
    model::design::ToolSounds sounds({});
    return sounds.sound("cryon", "office");
  }();
  return sound;
}

// Ten minutes of the paper's steps on the simulated rig, written to a session as fast as the
// simulation and the writer go: realtime_factor > 1 means a real-time capture keeps up; frames and
// dropped count what arrived and what was lost.
void BM_RigCaptureTenMinutes(benchmark::State& state) {
  const auto folder = std::filesystem::path(NIBRIG_TEST_BINARY_DIR) / "bench_rig_capture";
  for (auto _ : state) {
    std::filesystem::remove_all(folder);
    rig::SimulatedRigSettings settings;
    settings.speedup = 0.0;
    rig::SimulatedRig simulated(settings, cryon_office(), "cryon", "office");
    rig::CaptureOptions options;
    options.folder = folder;
    const auto start = std::chrono::steady_clock::now();
    const rig::CaptureResult result = rig::capture_session(simulated, rig::paper_steps(600.0), options);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    state.counters["seconds"] = result.record.seconds;
    state.counters["frames"] = static_cast<double>(result.record.frames);
    state.counters["dropped"] = static_cast<double>(result.record.dropped_frames);
    state.counters["realtime_factor"] = result.record.seconds / wall;
  }
  std::filesystem::remove_all(folder);
}
BENCHMARK(BM_RigCaptureTenMinutes)->Iterations(1)->Unit(benchmark::kSecond);

// Frames at 1 kHz posted to an engine playing through a real JACK server (dummy driver, 64-frame
// periods at 48 kHz: 1.33 ms); each frame's wait until the block that applies it.
void BM_RigFrameToContact(benchmark::State& state) {
  nibrig::testing::JackServer server({48000, 64});
  rt::EngineSettings engine_settings;
  engine_settings.slots = 1;
  playback::PreparedEngine session(engine_settings, cryon_office(),
                                   std::make_unique<rt::ConstantStroke>(0.0, 0.0), 1);
  rig::ContactFollower follower(session.engine());
  playback::OutputSettings output;
  output.api = "jack";
  output.period_frames = 64;
  output.stream_name = "bench-follow";
  playback::AudioOutput device(follower, output);
  for (auto _ : state) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(3);
    std::uint32_t k = 0;
    while (std::chrono::steady_clock::now() < until) {
      rig::SensorFrame frame;
      frame.sequence = k++;
      frame.speed_m_s = 0.05f + 0.0001f * static_cast<float>(k % 1000);
      frame.normal_force_N = 2.2f;
      follower.follow(frame);  // stamped with its post: no USB here
      session.engine().collect();
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  }
  const rig::FollowLatency latency = follower.latency();
  const auto info = device.stream_info();
  state.counters["period_ms"] = 1e3 * info.period_frames / info.sample_rate;
  state.counters["contacts"] = static_cast<double>(latency.contacts);
  state.counters["mean_ms"] = latency.mean_s * 1e3;
  state.counters["max_ms"] = latency.max_s * 1e3;
  state.counters["budget_ms"] = 1e3 * info.period_frames / info.sample_rate + 1.0;
}
BENCHMARK(BM_RigFrameToContact)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace
