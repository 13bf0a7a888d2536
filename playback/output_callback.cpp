#include "playback/output_callback.hpp"

#include <pthread.h>

#include <chrono>

#include <algorithm>

namespace nibrig::playback {

void OutputCallbackState::prepare(std::size_t period_frames) {
  if (period_frames > mono_frames) {
    mono = std::make_unique<float[]>(period_frames);
    mono_frames = period_frames;
  }
}

namespace {

int render_period(void* output, void* input, unsigned int frames, RtAudioStreamStatus status, void* user) noexcept {
  auto& s = *static_cast<OutputCallbackState*>(user);
  auto& c = s.counters;
  // First, before rendering: the closest the callback comes to when its input was handed over.
  const std::int64_t entered_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(
                                      std::chrono::steady_clock::now().time_since_epoch())
                                      .count();
  if (status & RTAUDIO_OUTPUT_UNDERFLOW)
    c.output_underflows.fetch_add(1, std::memory_order_relaxed);
  if (status & RTAUDIO_INPUT_OVERFLOW) c.input_overflows.fetch_add(1, std::memory_order_relaxed);

  // Non-interleaved layout (RTAUDIO_NONINTERLEAVED): channel k is the k-th run of `frames`.
  if (output != nullptr && s.mono_frames > 0) {
    auto* out = static_cast<float*>(output);
    for (unsigned ch = 0; ch < s.output_channels; ++ch) {
      if (ch != s.output_index) std::fill_n(out + std::size_t{ch} * frames, frames, 0.0f);
    }
    float* target = out + std::size_t{s.output_index} * frames;
    // A back end may hand a block longer than the period it promised; render it in pieces
    // rather than write past the buffer sized at open time.
    for (std::size_t done = 0; done < frames;) {
      const std::size_t n = std::min<std::size_t>(frames - done, s.mono_frames);
      s.renderer->render(s.mono.get(), n);
      std::copy_n(s.mono.get(), n, target + done);
      done += n;
    }
  }

  if (input != nullptr && s.capture != nullptr && s.input_channels > 0) {
    const auto* in = static_cast<const float*>(input) + std::size_t{s.input_index} * frames;
    const std::size_t stored = s.capture->push(in, frames);
    if (stored < frames) c.capture_dropped.fetch_add(frames - stored, std::memory_order_relaxed);
    if (s.stamps != nullptr) s.stamps->try_push({s.captured_samples, entered_ns});
    s.captured_samples += frames;
  }

  c.frames.fetch_add(frames, std::memory_order_relaxed);
  c.callbacks.fetch_add(1, std::memory_order_release);
  return 0;
}

}  // namespace

int output_callback(void* output, void* input, unsigned int frames, double /*stream_time*/,
                    RtAudioStreamStatus status, void* user) {
  // Deferred as well as disabled: glibc (2.36) still acts on a cancel signal arriving after the
  // disable while the type is asynchronous. Both are restored: JACK's own wait stays cancellable.
  int cancel_type = PTHREAD_CANCEL_DEFERRED;
  pthread_setcanceltype(PTHREAD_CANCEL_DEFERRED, &cancel_type);
  int cancel_state = PTHREAD_CANCEL_ENABLE;
  pthread_setcancelstate(PTHREAD_CANCEL_DISABLE, &cancel_state);
  const int result = render_period(output, input, frames, status, user);
  pthread_setcancelstate(cancel_state, nullptr);
  pthread_setcanceltype(cancel_type, nullptr);
  return result;
}

}  // namespace nibrig::playback
