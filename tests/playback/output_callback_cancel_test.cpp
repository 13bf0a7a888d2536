// JACK 2 cancels its client thread asynchronously (JackPosixThread::Kill) when a client is closed
// after its server died, wherever that thread is, inside the audio callback too. A forced unwind
// that meets a noexcept frame ends the whole process ("terminate called without an active
// exception", seen once in CI when the server was killed under a LiveAudition); the callback must
// let the cancellation end that thread alone.
#include <gtest/gtest.h>
#include <pthread.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>

#include "playback/output_callback.hpp"
#include "tests/playback/cancel_signal.hpp"

namespace nibrig::playback {
namespace {

// A step the compiler cannot see into and may not assume to be noexcept (as an engine's render
// calls many): a noexcept caller then carries the handler that ends the process on an unwind.
double (*volatile step)(double) = [](double x) { return std::sin(x) + 1.0; };

// Spends its time inside render, where a cancellation lands nearly every time.
class BusyRenderer : public rt::BlockRenderer {
 public:
  void render(float* out, std::size_t frames) noexcept override {
    for (std::size_t i = 0; i < frames; ++i) {
      double x = static_cast<double>(i);
      for (int k = 0; k < 200; ++k) x = step(x);
      out[i] = static_cast<float>(x);
    }
    calls.fetch_add(1, std::memory_order_release);
  }
  std::atomic<std::uint64_t> calls{0};
};

// What JACK's client thread does: asynchronous cancellation, then periods one after another.
void* audio_thread(void* state) {
  pthread_setcanceltype(PTHREAD_CANCEL_ASYNCHRONOUS, nullptr);
  static float buffer[256];
  for (;;) output_callback(buffer, nullptr, 256, 0.0, 0, state);
  return nullptr;
}

TEST(OutputCallback, AnAsynchronousCancelOfTheAudioThreadEndsThatThreadAlone) {
  BusyRenderer renderer;
  OutputCallbackState state;
  state.renderer = &renderer;
  state.output_channels = 1;
  state.prepare(256);
  for (int round = 0; round < 50; ++round) {
    pthread_t thread;
    ASSERT_EQ(pthread_create(&thread, nullptr, &audio_thread, &state), 0);
    const std::uint64_t before = renderer.calls.load(std::memory_order_acquire);
    while (renderer.calls.load(std::memory_order_acquire) < before + 2) std::this_thread::yield();
    ASSERT_EQ(pthread_cancel(thread), 0);
    // The thread loops for ever: joined, it was ended by the cancellation, and the process lives on.
    // (Its result is not checked: ASan's thread start, between glibc's and ours, does not pass
    // PTHREAD_CANCELED through.)
    ASSERT_EQ(pthread_join(thread, nullptr), 0) << "round " << round;
  }
}

// Lets the held cancel signal in from inside render, through a step that may throw as far as the
// compiler knows: the signal then lands where a noexcept render would end the process.
void (*volatile release_cancel)() = [] { testing::hold_cancel_signal(false); };

class ReleasingRenderer : public rt::BlockRenderer {
 public:
  void render(float* out, std::size_t frames) noexcept override {
    release_cancel();
    std::fill_n(out, frames, 0.0f);
    calls.fetch_add(1, std::memory_order_release);
  }
  std::atomic<int> calls{0};
};

struct LateCancel {
  OutputCallbackState* state = nullptr;
  std::atomic<bool> held{false};
  std::atomic<bool> sent{false};
  std::atomic<bool> survived{false};
};

// JACK's client thread, cancelled while it runs JACK's code and reached by the cancel signal only
// once the callback has disabled cancellation (here the signal is held until then; a loaded machine
// delays it the same way now and then).
void* late_cancel_thread(void* arg) {
  auto& late = *static_cast<LateCancel*>(arg);
  pthread_setcanceltype(PTHREAD_CANCEL_ASYNCHRONOUS, nullptr);
  testing::hold_cancel_signal(true);
  late.held.store(true, std::memory_order_release);
  while (!late.sent.load(std::memory_order_acquire)) std::this_thread::yield();
  static float buffer[64];
  output_callback(buffer, nullptr, 64, 0.0, 0, late.state);
  late.survived.store(true, std::memory_order_release);
  return nullptr;
}

// glibc 2.36's cancel signal handler checks the cancel type, not the state: a signal sent while
// cancellation was enabled acts on an asynchronous thread even after it disabled cancellation.
TEST(OutputCallback, ACancelSignalArrivingDuringTheRenderActsOnlyAfterIt) {
  ReleasingRenderer renderer;
  OutputCallbackState state;
  state.renderer = &renderer;
  state.output_channels = 1;
  state.prepare(64);
  LateCancel late;
  late.state = &state;
  pthread_t thread;
  ASSERT_EQ(pthread_create(&thread, nullptr, &late_cancel_thread, &late), 0);
  while (!late.held.load(std::memory_order_acquire)) std::this_thread::yield();
  ASSERT_EQ(pthread_cancel(thread), 0);  // enabled and asynchronous: the signal is sent, and held
  late.sent.store(true, std::memory_order_release);
  ASSERT_EQ(pthread_join(thread, nullptr), 0);
  EXPECT_EQ(renderer.calls.load(std::memory_order_acquire), 1) << "the render was cut short";
  EXPECT_FALSE(late.survived.load(std::memory_order_acquire)) << "the cancellation was lost";
}

}  // namespace
}  // namespace nibrig::playback
