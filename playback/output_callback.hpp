// The part of AudioOutput that runs on the audio thread: render one mono block, place it in the
// chosen output channel, silence the others, push the chosen input channel into the capture ring
// and count. Everything it touches is allocated before the stream starts.
#pragma once

#include <rtaudio/RtAudio.h>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>

#include "playback/capture_stamp.hpp"
#include "playback/sample_ring.hpp"
#include "rt/block_renderer.hpp"
#include "rt/spsc_queue.hpp"

namespace nibrig::playback {

// Counters written by the audio thread and read by anyone (relaxed: they are statistics, and the
// callback count doubles as the heartbeat the supervisor watches).
struct CallbackCounters {
  std::atomic<std::uint64_t> callbacks{0};
  std::atomic<std::uint64_t> frames{0};
  std::atomic<std::uint64_t> output_underflows{0};
  std::atomic<std::uint64_t> input_overflows{0};
  std::atomic<std::uint64_t> capture_dropped{0};
};

// Shared between the control side and the callback. The layout fields may change only while no
// stream is running (between open and start), which is when `prepare` is called.
struct OutputCallbackState {
  rt::BlockRenderer* renderer = nullptr;
  std::unique_ptr<float[]> mono;
  std::size_t mono_frames = 0;
  unsigned output_channels = 0;  // channels of the opened stream, non-interleaved
  unsigned output_index = 0;     // 0-based channel that carries the signal
  unsigned input_channels = 0;   // 0: no input stream
  unsigned input_index = 0;      // 0-based channel that is captured
  SampleRing* capture = nullptr;
  rt::SpscQueue<CaptureStamp>* stamps = nullptr;  // one per callback with input; full: dropped
  std::uint64_t captured_samples = 0;             // audio thread only
  CallbackCounters counters;

  // Sizes the mono buffer for blocks of `period_frames` (allocates: control thread only).
  void prepare(std::size_t period_frames);
};

// RtAudio's callback. `user` is an OutputCallbackState. Never allocates, locks, logs or throws.
// Not noexcept itself: JACK 2 cancels its client thread asynchronously when the client closes
// after the server died (JackPosixThread::Kill), and a cancellation's forced unwind that meets a
// noexcept frame ends the process. The period is rendered with cancellation disabled and deferred
// (a cancel signal already on its way would act on a disabled but asynchronous thread); a pending
// cancel then unwinds from here, past no noexcept frame of ours.
int output_callback(void* output, void* input, unsigned int frames, double stream_time,
                    RtAudioStreamStatus status, void* user);

}  // namespace nibrig::playback
