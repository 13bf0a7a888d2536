#include "playback/audio_output.hpp"

#include <rtaudio/RtAudio.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <condition_variable>
#include <iostream>
#include <mutex>
#include <thread>
#include <utility>

#include "playback/alsa_quiet.hpp"
#include "playback/audio_devices.hpp"
#include "playback/device_error.hpp"
#include "playback/device_probe.hpp"
#include "playback/output_callback.hpp"
#include "playback/sample_ring.hpp"

namespace nibrig::playback {
namespace {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

// How often the supervisor looks at the stream. A JACK period is 1-20 ms; the loss itself is
// reported by the back end, so this only bounds how late the report is noticed.
constexpr milliseconds kPoll{20};
// RtAudio's JACK back end closes a stream from a thread of its own once the server is gone; the
// supervisor waits this long for it before closing the stream itself.
constexpr milliseconds kBackendCloseGrace{1000};

std::string rates_text(const std::vector<unsigned>& rates) {
  std::string text;
  for (unsigned r : rates) text += (text.empty() ? "" : ", ") + std::to_string(r);
  return text.empty() ? "none reported" : text + " Hz";
}

}  // namespace

struct AudioOutput::Impl {
  OutputSettings settings;
  std::string api;           // resolved short name
  std::string device;        // resolved exact name: what a reopen looks for
  std::string input_device;  // the same for the input; equal to device unless one was named
  RtAudio::Api api_id = RtAudio::UNSPECIFIED;
  std::unique_ptr<SampleRing> ring;
  std::unique_ptr<rt::SpscQueue<CaptureStamp>> stamps;
  OutputCallbackState state;

  // Owned by the constructing thread until the supervisor starts, then by the supervisor alone:
  // RtAudio objects are not thread-safe.
  std::unique_ptr<RtAudio> rt;

  std::atomic<OutputStatus> status{OutputStatus::running};
  std::atomic<std::uint64_t> losses{0};
  std::atomic<std::uint64_t> reconnects{0};

  mutable std::mutex info_mutex;
  StreamInfo info;
  std::string problem;

  std::mutex stop_mutex;
  std::condition_variable stop_cv;
  bool stop = false;
  std::thread supervisor;

  std::string asked() const {
    std::string text = api + " device '" + device + "' at " + std::to_string(settings.sample_rate) +
                       " Hz, period " + std::to_string(settings.period_frames) +
                       " frames, output channel " + std::to_string(settings.output_channel);
    if (settings.input_channel) {
      text += ", input channel " + std::to_string(*settings.input_channel);
      if (input_device != device) text += " of '" + input_device + "'";
    }
    return text;
  }

  void set_problem(std::string text) {
    std::lock_guard lock(info_mutex);
    problem = std::move(text);
  }

  void validate_input(const DeviceInfo& d) const {
    if (settings.input_channel &&
        (*settings.input_channel < 1 || *settings.input_channel > d.input_channels)) {
      throw DeviceError("input channel " + std::to_string(*settings.input_channel) +
                        " is out of range: " + api + " device '" + d.name + "' has " +
                        std::to_string(d.input_channels) + " input channels (1-based)");
    }
    if (d.name != device) validate_rate(d);
  }

  void validate(const DeviceInfo& d) const {
    const std::string who = api + " device '" + d.name + "'";
    if (settings.output_channel < 1 || settings.output_channel > d.output_channels) {
      throw DeviceError("output channel " + std::to_string(settings.output_channel) +
                        " is out of range: " + who + " has " + std::to_string(d.output_channels) +
                        " output channels (1-based)");
    }
    validate_rate(d);
  }

  void validate_rate(const DeviceInfo& d) const {
    const std::string who = api + " device '" + d.name + "'";
    const auto& rates = d.sample_rates;
    if (std::find(rates.begin(), rates.end(), settings.sample_rate) == rates.end()) {
      std::string text = who + " does not support " + std::to_string(settings.sample_rate) +
                         " Hz; it supports " + rates_text(rates);
      if (api_id == RtAudio::UNIX_JACK) {
        text += " (JACK runs only at the rate its server was started with, jackd -r)";
      }
      throw DeviceError(text);
    }
  }

  // Finds the device by its exact name on a fresh RtAudio, checks it, opens and starts the stream.
  std::unique_ptr<RtAudio> open() {
    quiet_alsa_library();
    auto fresh = std::make_unique<RtAudio>(api_id);
    fresh->showWarnings(false);
    DeviceTable table;
    try {
      table = probe_devices(*fresh, ProbePatience::opening);
    } catch (const RtAudioError& e) {
      throw DeviceError("cannot list " + api + " devices to find '" + device + "': " + e.what());
    }
    const auto it = std::find_if(table.devices.begin(), table.devices.end(),
                                 [&](const ProbedDevice& d) { return d.info.name == device; });
    if (it == table.devices.end()) {
      std::string names;
      for (const ProbedDevice& d : table.devices) {
        names += (names.empty() ? "'" : ", '") + d.info.name + "'";
      }
      if (table.unprobed > 0) names += " and " + std::to_string(table.unprobed) + " unprobed";
      throw DeviceError(
          api + " device '" + device + "' is not there (" +
          (table.count == 0 ? "no devices: is the server running?" : "devices: " + names) + ")");
    }
    const unsigned index = it->index;
    const DeviceInfo& found = it->info;
    validate(found);
    auto input = it;
    if (settings.input_channel && input_device != device) {
      input = std::find_if(table.devices.begin(), table.devices.end(),
                           [&](const ProbedDevice& d) { return d.info.name == input_device; });
      if (input == table.devices.end())
        throw DeviceError(api + " input device '" + input_device + "' is not there");
    }
    validate_input(input->info);

    RtAudio::StreamParameters out;
    out.deviceId = index;
    out.nChannels = found.output_channels;
    out.firstChannel = 0;
    RtAudio::StreamParameters in;
    in.deviceId = input->index;
    in.nChannels = settings.input_channel ? input->info.input_channels : 0;
    in.firstChannel = 0;
    RtAudio::StreamOptions options;
    options.flags = RTAUDIO_NONINTERLEAVED;
    if (!settings.connect_ports) options.flags |= RTAUDIO_JACK_DONT_CONNECT;
    options.streamName = settings.stream_name;

    // The stream is not running: the callback cannot see the layout change.
    state.output_channels = found.output_channels;
    state.output_index = settings.output_channel - 1;
    state.input_channels = in.nChannels;
    state.input_index = settings.input_channel ? *settings.input_channel - 1 : 0;

    unsigned frames = settings.period_frames;
    for (int attempt = 1;; ++attempt) {
      try {
        frames = settings.period_frames;
        fresh->openStream(&out, settings.input_channel ? &in : nullptr, RTAUDIO_FLOAT32,
                          settings.sample_rate, &frames, &output_callback, &state, &options);
        break;
      } catch (const RtAudioError& e) {
        // openStream counts the devices again through a temporary JACK client, which a busy
        // server refuses now and then ("output device parameter value is invalid", seen in CI),
        // as in probing; a lasting fault fails the same way every time and is reported.
        if (attempt == probe_attempts(ProbePatience::opening))
          throw DeviceError("cannot open " + asked() + ": " + e.what());
        std::this_thread::sleep_for(probe_retry_pause(attempt));
      }
    }
    state.prepare(frames);
    try {
      fresh->startStream();
    } catch (const RtAudioError& e) {
      try {
        fresh->closeStream();
      } catch (const RtAudioError&) {
      }
      throw DeviceError("cannot start " + asked() + ": " + e.what());
    }

    StreamInfo opened;
    opened.api = api;
    opened.device = device;
    opened.sample_rate = settings.sample_rate;
    opened.period_frames = frames;
    opened.output_channels = found.output_channels;
    opened.input_channels = in.nChannels;
    if (settings.input_channel) opened.input_device = input_device;
    try {
      opened.latency_frames = fresh->getStreamLatency();
    } catch (const RtAudioError&) {
    }
    std::lock_guard lock(info_mutex);
    info = opened;
    return fresh;
  }

  // Polls until the audio callback has run `count` more times, up to `timeout`. One callback
  // proves nothing: the cycle in flight when a server dies still completes.
  bool heartbeat_within(milliseconds timeout, std::uint64_t count) const {
    const std::uint64_t before = state.counters.callbacks.load(std::memory_order_acquire);
    const auto deadline = Clock::now() + timeout;
    while (Clock::now() < deadline) {
      if (state.counters.callbacks.load(std::memory_order_acquire) - before >= count) return true;
      std::this_thread::sleep_for(milliseconds(1));
    }
    return false;
  }

  // Closes and drops the RtAudio object of a stream that may be dead.
  void release_lost_stream() noexcept {
    if (!rt) return;
    try {
      if (api_id == RtAudio::UNIX_JACK) {
        // RtAudio 5.2's JACK shutdown handler closes the stream from a thread it spawns, without
        // a lock: closing it here at the same time would free its buffers twice. Let it finish.
        // (Reading the stream state while that thread writes it is a race RtAudio leaves us.)
        const auto deadline = Clock::now() + kBackendCloseGrace;
        while (rt->isStreamOpen() && Clock::now() < deadline) {
          std::this_thread::sleep_for(milliseconds(5));
        }
      }
      if (rt->isStreamOpen()) rt->closeStream();
    } catch (...) {
      // Closing a stream whose device is gone may report errors; nothing is left to do with it.
    }
    try {
      rt.reset();
    } catch (...) {
    }
  }

  void close_on_exit() noexcept {
    if (!rt) return;
    // A stream whose server still runs cycles is closed at once. One whose callbacks stopped may
    // be mid-close by RtAudio's own shutdown thread (closing it here too would free it twice), so
    // it is treated as lost. A server dying within the few milliseconds of closeStream() itself
    // is a window RtAudio 5.2 leaves open: its shutdown handler takes no lock.
    bool healthy = false;
    try {
      healthy = status.load() == OutputStatus::running && rt->isStreamOpen() &&
                heartbeat_within(std::max(milliseconds(100), settings.stall_timeout / 4), 3);
    } catch (...) {
    }
    if (!healthy) {
      release_lost_stream();
      return;
    }
    try {
      rt->closeStream();
    } catch (...) {
    }
    try {
      rt.reset();
    } catch (...) {
    }
  }

  void supervise() noexcept {
    std::uint64_t seen = state.counters.callbacks.load(std::memory_order_acquire);
    auto progress = Clock::now();
    auto lost_at = Clock::now();
    auto next_attempt = Clock::now();
    std::string last_reported;
    std::unique_lock lock(stop_mutex);
    while (!stop) {
      stop_cv.wait_for(lock, kPoll);
      if (stop) break;
      lock.unlock();
      try {
        const auto now = Clock::now();
        if (status.load() == OutputStatus::running) {
          const std::uint64_t calls = state.counters.callbacks.load(std::memory_order_acquire);
          if (calls != seen) {
            seen = calls;
            progress = now;
          }
          const bool closed = !rt->isStreamOpen();
          const bool stalled = now - progress > settings.stall_timeout;
          if (closed || stalled) {
            const std::string why =
                closed ? "the " + api + " back end closed the stream (server or device gone)"
                       : "no audio callback for " +
                             std::to_string(
                                 std::chrono::duration_cast<milliseconds>(now - progress).count()) +
                             " ms";
            set_problem(why);
            spdlog::warn("audio output: {} device '{}' lost: {}; reopening it every {} ms", api,
                         device, why, settings.retry_interval.count());
            losses.fetch_add(1);
            status.store(OutputStatus::lost);
            lost_at = now;
            release_lost_stream();
            last_reported.clear();
            next_attempt = Clock::now() + settings.retry_interval;
          }
        } else if (now >= next_attempt) {
          try {
            rt = open();
            seen = state.counters.callbacks.load(std::memory_order_acquire);
            progress = Clock::now();
            reconnects.fetch_add(1);
            set_problem({});
            status.store(OutputStatus::running);
            spdlog::info("audio output: {} device '{}' is back after {:.2f} s; stream restarted",
                         api, device, std::chrono::duration<double>(progress - lost_at).count());
          } catch (const std::exception& e) {
            set_problem(std::string("device lost; reopening failed: ") + e.what());
            if (last_reported != e.what()) {
              spdlog::info("audio output: waiting for {} device '{}': {}", api, device, e.what());
              last_reported = e.what();
            }
          }
          next_attempt = Clock::now() + settings.retry_interval;
        }
      } catch (...) {
        // Nothing may escape this thread; the next poll looks again.
      }
      lock.lock();
    }
    lock.unlock();
    close_on_exit();
  }
};

AudioOutput::AudioOutput(rt::BlockRenderer& renderer, OutputSettings settings)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  if (settings.output_channel < 1) {
    throw DeviceError("output channel 0 is out of range: channels are numbered from 1");
  }
  if (settings.input_channel && *settings.input_channel < 1) {
    throw DeviceError("input channel 0 is out of range: channels are numbered from 1");
  }
  if (settings.sample_rate == 0 || settings.period_frames == 0) {
    throw DeviceError("sample rate and period must be positive (asked " +
                      std::to_string(settings.sample_rate) + " Hz, " +
                      std::to_string(settings.period_frames) + " frames)");
  }
  if (settings.stream_name.empty()) throw DeviceError("an audio stream needs a name");

  const DeviceChoice choice = choose_device(settings.api, settings.device);
  m.settings = std::move(settings);
  m.api = choice.api;
  m.device = choice.device.name;
  m.input_device = m.device;
  m.api_id = RtAudio::getCompiledApiByName(m.api);
  if (m.api_id == RtAudio::UNIX_JACK) {
    // RtAudio 5.2's JACK shutdown handler prints to std::cerr on libjack's notification thread
    // while its own closing thread cancels that thread asynchronously. Without unitbuf (stderr is
    // unbuffered anyway) no insertion flushes inside ostream::sentry's noexcept destructor, where
    // such a cancel ends the process.
    std::cerr.unsetf(std::ios_base::unitbuf);
  }
  m.validate(choice.device);
  if (m.settings.input_channel) {
    const DeviceInfo input = m.settings.input_device.empty()
                                 ? choice.device
                                 : choose_device(m.api, m.settings.input_device).device;
    m.input_device = input.name;
    m.validate_input(input);
  }

  m.state.renderer = &renderer;
  if (m.settings.input_channel) {
    m.ring = std::make_unique<SampleRing>(m.settings.capture_capacity);
    m.state.capture = m.ring.get();
    m.stamps = std::make_unique<rt::SpscQueue<CaptureStamp>>(4096);  // seconds of callbacks
    m.state.stamps = m.stamps.get();
  }
  m.rt = m.open();
  const StreamInfo opened = stream_info();
  spdlog::info("audio output: {} device '{}' open at {} Hz, period {} frames, output channel {}",
               opened.api, opened.device, opened.sample_rate, opened.period_frames,
               m.settings.output_channel);
  m.supervisor = std::thread([&m] { m.supervise(); });
}

AudioOutput::~AudioOutput() {
  {
    std::lock_guard lock(impl_->stop_mutex);
    impl_->stop = true;
  }
  impl_->stop_cv.notify_all();
  if (impl_->supervisor.joinable()) impl_->supervisor.join();
}

OutputStatus AudioOutput::status() const noexcept { return impl_->status.load(); }

OutputStats AudioOutput::stats() const noexcept {
  const CallbackCounters& c = impl_->state.counters;
  OutputStats s;
  s.callbacks = c.callbacks.load(std::memory_order_relaxed);
  s.frames = c.frames.load(std::memory_order_relaxed);
  s.output_underflows = c.output_underflows.load(std::memory_order_relaxed);
  s.input_overflows = c.input_overflows.load(std::memory_order_relaxed);
  s.capture_dropped = c.capture_dropped.load(std::memory_order_relaxed);
  s.losses = impl_->losses.load();
  s.reconnects = impl_->reconnects.load();
  return s;
}

StreamInfo AudioOutput::stream_info() const {
  std::lock_guard lock(impl_->info_mutex);
  return impl_->info;
}

std::string AudioOutput::last_problem() const {
  std::lock_guard lock(impl_->info_mutex);
  return impl_->problem;
}

std::size_t AudioOutput::read_captured(float* out, std::size_t max) noexcept {
  return impl_->ring ? impl_->ring->pop(out, max) : 0;
}

std::size_t AudioOutput::read_capture_stamps(CaptureStamp* out, std::size_t max) noexcept {
  std::size_t n = 0;
  if (!impl_->stamps) return 0;
  while (n < max) {
    const auto stamp = impl_->stamps->try_pop();
    if (!stamp) break;
    out[n++] = *stamp;
  }
  return n;
}

std::size_t AudioOutput::captured_available() const noexcept {
  return impl_->ring ? impl_->ring->size() : 0;
}

}  // namespace nibrig::playback
