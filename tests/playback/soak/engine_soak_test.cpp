// The real-time path's soak on a real JACK server (dummy driver, 48 kHz, 64-frame periods): a
// minute of streaming under a flood of contact updates, voice swaps and strokes allocates nothing
// on the audio thread and does not overrun its periods (one block aside: see the bound). Its time
// is the point, so it is a suite of its own that CI builds and runs in Release, the build that
// plays (tests/CMakeLists.txt).
#include <gtest/gtest.h>
#include <unistd.h>

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

// The host's stolen time so far, from /proc/stat (s): a virtual CPU's thread CPU time can include
// what the host took meanwhile. Printed beside a minute's overruns, so that a failure says whether
// the host was busy.
double stolen_seconds() {
  std::FILE* f = std::fopen("/proc/stat", "r");
  if (!f) return 0.0;
  unsigned long long user = 0, nice = 0, system = 0, idle = 0, iowait = 0, irq = 0, softirq = 0,
                     steal = 0;
  const int read = std::fscanf(f, "cpu %llu %llu %llu %llu %llu %llu %llu %llu", &user, &nice,
                               &system, &idle, &iowait, &irq, &softirq, &steal);
  std::fclose(f);
  return read == 8 ? static_cast<double>(steal) / static_cast<double>(sysconf(_SC_CLK_TCK)) : 0.0;
}

// What the test asserts of a minute (the rest is printed).
struct SoakMinute {
  std::uint64_t calls = 0, contacts = 0, swaps = 0, overruns = 0;
  std::size_t allocations = 0;
  double max_cpu_s = 0, peak = 0;
};

// A minute of streaming under the flood, on a JACK server of its own.
SoakMinute soak_a_minute() {
  nibrig::testing::JackServer server;
  rt::Engine engine{rt::EngineSettings{}};
  SoakMinute minute;
  EXPECT_TRUE(engine.load(0, catalog_voice("stab", "note", engine.internal_rate(), 1)));
  std::vector<std::unique_ptr<rt::Voice>> spare;
  const char* tools[] = {"cryon", "vero2", "stab"};
  for (std::size_t i = 0; i < 40; ++i) spare.push_back(catalog_voice(tools[i % 3], "note", engine.internal_rate(), 10 + i));
  CountingRenderer renderer(engine);
  AudioOutput output(renderer, testing::jack_settings("soak"));
  if (testing::wait_until([&] { return renderer.calls() > 1; }, 5s).count() < 0.0) {
    ADD_FAILURE() << "the stream did not start within 5 s";
    return minute;
  }

  const double stolen_before = stolen_seconds();
  std::atomic<bool> done{false};
  std::thread flood([&] {
    for (std::uint64_t i = 0; !done.load(); ++i) {
      minute.contacts +=
          engine.set_contact(0.01 + 0.25 * ((i % 1000) / 1000.0), 0.5 + (i % 9) * 0.4);
      if (i % 2000 == 0 && !spare.empty() && engine.load(i / 2000 % 3, std::move(spare.back()))) {
        spare.pop_back();
        ++minute.swaps;
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
  const double stolen_s = stolen_seconds() - stolen_before;
  minute.calls = renderer.calls();
  minute.allocations = renderer.allocations();
  minute.overruns = stats.overruns;
  minute.max_cpu_s = stats.max_callback_cpu_s;
  minute.peak = stats.peak_output;
  std::printf(
      "soak: %llu callbacks, %llu contact updates, %llu voice swaps; engine overruns %llu (largest "
      "CPU time of a block %.1f us); callback wall time median <= %.1f us, 99th percentile <= "
      "%.1f us, max %.1f us; device underflows %llu (the dummy driver's late cycles); the host "
      "stole %.2f s of CPU meanwhile\n",
      static_cast<unsigned long long>(minute.calls),
      static_cast<unsigned long long>(minute.contacts),
      static_cast<unsigned long long>(minute.swaps),
      static_cast<unsigned long long>(minute.overruns), 1e6 * minute.max_cpu_s,
      1e6 * stats.callback_time_quantile(0.5), 1e6 * stats.callback_time_quantile(0.99),
      1e6 * stats.max_callback_s, static_cast<unsigned long long>(output.stats().output_underflows),
      stolen_s);
  return minute;
}

// Overruns are CPU time above the period, measured inside the callback (preemption and the dummy
// driver's xruns are not ours and not counted). The forcing generator spreads its hop over the
// calls, so no callback moves every warm voice's frames at once and even the largest block under
// the flood stays well inside the period.
// Under the sanitizers every block costs several times its Release time, and ASan's own work (its
// shadow memory's first touches, its allocator's bookkeeping for the other threads) lands in the
// callback now and then, a few blocks in tens of thousands: there one block in 2000 is allowed.
// In Release one block in the minute may pass its period: a kernel without IRQ time accounting
// (CI's and this machine's) charges the interrupts it serves to the thread they interrupt, and
// once in CI a block read 2.7 ms of "CPU time" against 1.3 ms at most in three runs here.
std::uint64_t overruns_allowed(std::uint64_t calls) {
#if defined(__SANITIZE_ADDRESS__)
  return calls / 2000;
#else
  (void)calls;
  return 1;
#endif
}

TEST(EnginePlayback, AMinuteUnderAFloodOfUpdatesAllocatesNothingAndNeverOverruns) {
  SoakMinute minute = soak_a_minute();
  EXPECT_EQ(minute.allocations, 0u) << "over " << minute.calls << " callbacks";
  // A loaded host can still charge a virtual CPU's thread with time it did not run, many blocks of
  // one minute at once: a second minute then. An engine's own slow path repeats with what causes
  // it, the minute's 40 voice swaps and thousands of forcing hops, and misses both.
  if (minute.overruns > overruns_allowed(minute.calls)) {
    std::printf("%llu overruns in the first minute; a second minute\n",
                static_cast<unsigned long long>(minute.overruns));
    minute = soak_a_minute();
    EXPECT_EQ(minute.allocations, 0u) << "over " << minute.calls << " callbacks";
  }
  EXPECT_LE(minute.overruns, overruns_allowed(minute.calls))
      << "largest CPU time of a block " << 1e6 * minute.max_cpu_s << " us";
  EXPECT_GT(minute.calls, 20000u);  // 60 s of 64-frame periods is 45,000
  EXPECT_GT(minute.swaps, 20u);
  EXPECT_GT(minute.contacts, 100000u);
  EXPECT_LE(minute.peak, rt::EngineSettings{}.output.limit);
}

}  // namespace
}  // namespace nibrig::playback
