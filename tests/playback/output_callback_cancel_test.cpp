// JACK 2 cancels its client thread asynchronously (JackPosixThread::Kill) when a client is closed
// after its server died, wherever that thread is, inside the audio callback too. A forced unwind
// that meets a noexcept frame ends the whole process ("terminate called without an active
// exception", seen once in CI when the server was killed under a LiveAudition); the callback must
// let the cancellation end that thread alone.
#include <gtest/gtest.h>
#include <pthread.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>

#include "playback/output_callback.hpp"

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

}  // namespace
}  // namespace nibrig::playback
