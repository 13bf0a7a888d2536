// The playback tests' deterministic source: each sample is a pure function of its frame index
// (two sines at unrelated frequencies plus a slow ramp, so no stretch of it repeats within a
// test), which lets a test recompute offline exactly what the device should have played.
#pragma once

#include <jack/jack.h>
#include <pthread.h>

#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <vector>

#include "rt/block_renderer.hpp"
#include "tests/support/allocation_counter.hpp"

namespace nibrig::playback::testing {

inline float test_signal(std::uint64_t frame) {
  const double n = static_cast<double>(frame);
  constexpr double kRate = 48000.0;
  const double a = 0.25 * std::sin(2.0 * std::numbers::pi * 441.3 * n / kRate);
  const double b = 0.2 * std::sin(2.0 * std::numbers::pi * 1723.9 * n / kRate + 0.3);
  const double ramp = 0.05 + 0.3 * n / 4.0e6;  // an offset, so that played is rarely exactly 0
  return static_cast<float>(a + b + ramp);
}

class SignalRenderer : public rt::BlockRenderer {
 public:
  // `max_calls` bounds the preallocated log of per-call frame times.
  explicit SignalRenderer(std::size_t max_calls = 1 << 16) : call_times_(max_calls, 0) {}

  // A JACK client of the same server whose frame clock stamps each call (optional).
  void set_clock(jack_client_t* client) { clock_.store(client, std::memory_order_release); }

  void render(float* out, std::size_t frames) noexcept override {
    const std::uint64_t call = calls_.load(std::memory_order_relaxed);
    if (call == 0) {
      first_allocations_ = nibrig::testing::allocations_on_this_thread();
      first_thread_ = pthread_self();
    }
    if (jack_client_t* c = clock_.load(std::memory_order_acquire); c && call < call_times_.size()) {
      call_times_[call] = jack_last_frame_time(c);
    }
    for (std::size_t i = 0; i < frames; ++i) out[i] = test_signal(next_frame_ + i);
    next_frame_ += frames;
    last_allocations_.store(nibrig::testing::allocations_on_this_thread(),
                            std::memory_order_relaxed);
    last_thread_.store(pthread_self(), std::memory_order_relaxed);
    calls_.store(call + 1, std::memory_order_release);
  }

  std::uint64_t calls() const { return calls_.load(std::memory_order_acquire); }
  std::uint64_t frames() const { return next_frame_; }  // read after the stream stopped
  // Allocations by the audio thread at the start of its first call and the end of its latest.
  std::size_t first_allocations() const { return first_allocations_; }
  std::size_t last_allocations() const { return last_allocations_.load(std::memory_order_relaxed); }
  bool same_thread_throughout() const {
    return pthread_equal(first_thread_, last_thread_.load(std::memory_order_relaxed)) != 0;
  }
  // The server frame time at the start of call `call` (0 when no clock was set then).
  jack_nframes_t call_time(std::size_t call) const { return call_times_.at(call); }

 private:
  std::atomic<jack_client_t*> clock_{nullptr};
  std::vector<jack_nframes_t> call_times_;
  std::uint64_t next_frame_ = 0;
  std::atomic<std::uint64_t> calls_{0};
  std::size_t first_allocations_ = 0;
  pthread_t first_thread_{};
  std::atomic<std::size_t> last_allocations_{0};
  std::atomic<pthread_t> last_thread_{};
};

// What `SignalRenderer` produces for its first `frames` frames, rendered offline in blocks of
// `block` through the same render() the device calls.
inline std::vector<float> render_offline(std::size_t frames, std::size_t block) {
  SignalRenderer renderer(1);
  std::vector<float> out(frames);
  for (std::size_t at = 0; at < frames; at += block) {
    renderer.render(out.data() + at, std::min(block, frames - at));
  }
  return out;
}

}  // namespace nibrig::playback::testing
