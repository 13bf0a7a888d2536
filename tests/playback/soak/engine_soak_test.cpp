// The real-time path's soak on a real JACK server (dummy driver, 48 kHz, 64-frame periods): a
// minute of streaming under a flood of contact updates, voice swaps and strokes allocates nothing
// on the audio thread and does not overrun its periods (one block aside: see the bound). Its time
// is the point, so it is a suite of its own that CI builds and runs in Release, the build that
// plays (tests/CMakeLists.txt).
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <memory>
#include <thread>
#include <vector>

#include "playback/audio_output.hpp"
#include "rt/engine.hpp"
#include "tests/playback/jack_stream_settings.hpp"
#include "tests/playback/wait_until.hpp"
#include "tests/rt/test_voices.hpp"
#include "tests/support/allocation_counter.hpp"
#include "tests/support/jack_server.hpp"

namespace nibrig::playback {
namespace {

using namespace std::chrono_literals;

using rt::testing::catalog_voice;

// Forwards to the engine and notes the audio thread's allocation count at every call.
class CountingRenderer final : public rt::BlockRenderer {
 public:
  explicit CountingRenderer(rt::Engine& engine) : engine_(engine) {}
  void render(float* out, std::size_t frames) noexcept override {
    const std::size_t now = nibrig::testing::allocations_on_this_thread();
    if (calls_.load(std::memory_order_relaxed) == 1) first_.store(now, std::memory_order_relaxed);
    latest_.store(now, std::memory_order_relaxed);
    calls_.fetch_add(1, std::memory_order_relaxed);
    engine_.render(out, frames);
  }
  // Allocations between the second call and the latest (the first may warm RtAudio up).
  std::size_t allocations() const { return latest_.load() - first_.load(); }
  std::uint64_t calls() const { return calls_.load(); }

 private:
  rt::Engine& engine_;
  std::atomic<std::uint64_t> calls_{0};
  std::atomic<std::size_t> first_{0}, latest_{0};
};

TEST(EnginePlayback, AMinuteUnderAFloodOfUpdatesAllocatesNothingAndNeverOverruns) {
  nibrig::testing::JackServer server;
  rt::Engine engine{rt::EngineSettings{}};
  ASSERT_TRUE(engine.load(0, catalog_voice("stab", "note", engine.internal_rate(), 1)));
  std::vector<std::unique_ptr<rt::Voice>> spare;
  const char* tools[] = {"cryon", "vero2", "stab"};
  for (std::size_t i = 0; i < 40; ++i) spare.push_back(catalog_voice(tools[i % 3], "note", engine.internal_rate(), 10 + i));
  CountingRenderer renderer(engine);
  AudioOutput output(renderer, testing::jack_settings("soak"));
  ASSERT_GE(testing::wait_until([&] { return renderer.calls() > 1; }, 5s).count(), 0.0);

  std::atomic<bool> done{false};
  std::uint64_t contacts = 0, swaps = 0;
  std::thread flood([&] {
    for (std::uint64_t i = 0; !done.load(); ++i) {
      contacts += engine.set_contact(0.01 + 0.25 * ((i % 1000) / 1000.0), 0.5 + (i % 9) * 0.4);
      if (i % 2000 == 0 && !spare.empty() && engine.load(i / 2000 % 3, std::move(spare.back()))) {
        spare.pop_back();
        ++swaps;
      }
      if (i % 700 == 0) engine.select(i / 700 % 3);
      if (i % 5000 == 0) engine.attach(std::make_unique<rt::SweepStroke>());
      engine.collect();
      std::this_thread::sleep_for(50us);
    }
  });
  std::this_thread::sleep_for(60s);
  done = true;
  flood.join();

  const auto stats = engine.stats();
  const auto device = output.stats();
  EXPECT_EQ(renderer.allocations(), 0u) << "over " << renderer.calls() << " callbacks";
  // Overruns are CPU time above the period, measured inside the callback (preemption and the
  // dummy driver's xruns are not ours and not counted). The forcing generator spreads its hop over
  // the calls, so no callback moves every warm voice's frames at once and even the largest block
  // under the flood stays well inside the period.
  // Under the sanitizers every block costs several times its Release time, and ASan's own work (its
  // shadow memory's first touches, its allocator's bookkeeping for the other threads) lands in the
  // callback now and then, a few blocks in tens of thousands: there one block in 2000 is allowed.
  // In Release one block in the minute may pass its period: a kernel without IRQ time accounting
  // (CI's and this machine's) charges the interrupts it serves to the thread they interrupt, and
  // once in CI a block read 2.7 ms of "CPU time" against 1.3 ms at most in three runs here. An
  // engine's own slow path repeats with what causes it: the minute's 40 voice swaps, its thousands
  // of forcing hops.
#if defined(__SANITIZE_ADDRESS__)
  EXPECT_LE(stats.overruns, renderer.calls() / 2000)
#else
  EXPECT_LE(stats.overruns, 1u)
#endif
      << "largest CPU time of a block " << 1e6 * stats.max_callback_cpu_s << " us";
  EXPECT_GT(renderer.calls(), 20000u);  // 60 s of 64-frame periods is 45,000
  EXPECT_GT(swaps, 20u);
  EXPECT_GT(contacts, 100000u);
  EXPECT_LE(stats.peak_output, rt::EngineSettings{}.output.limit);
  std::printf(
      "soak: %llu callbacks, %llu contact updates, %llu voice swaps; engine overruns %llu (largest "
      "CPU time of a block %.1f us); callback wall time median <= %.1f us, 99th percentile <= "
      "%.1f us, max %.1f us; "
      "device underflows %llu (the dummy driver's late cycles)\n",
      static_cast<unsigned long long>(renderer.calls()), static_cast<unsigned long long>(contacts),
      static_cast<unsigned long long>(swaps), static_cast<unsigned long long>(stats.overruns),
      1e6 * stats.max_callback_cpu_s, 1e6 * stats.callback_time_quantile(0.5), 1e6 * stats.callback_time_quantile(0.99),
      1e6 * stats.max_callback_s, static_cast<unsigned long long>(device.output_underflows));
}

}  // namespace
}  // namespace nibrig::playback
