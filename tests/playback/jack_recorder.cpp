#include "tests/playback/jack_recorder.hpp"

#include <algorithm>
#include <ctime>
#include <stdexcept>
#include <thread>

namespace nibrig::playback::testing {

JackRecorder::JackRecorder(const std::string& name, std::size_t ports, std::size_t capacity_frames)
    : name_(name), capacity_(capacity_frames), cycles_(capacity_frames / 16 + 2) {
  jack_status_t status{};
  client_ = jack_client_open(
      name.c_str(), static_cast<jack_options_t>(JackNoStartServer | JackUseExactName), &status);
  if (client_ == nullptr) {
    throw std::runtime_error("JackRecorder: cannot open JACK client '" + name + "' (status 0x" +
                             std::to_string(static_cast<unsigned>(status)) + ")");
  }
  for (std::size_t i = 0; i < ports; ++i) {
    const std::string port = "in_" + std::to_string(i + 1);
    jack_port_t* p =
        jack_port_register(client_, port.c_str(), JACK_DEFAULT_AUDIO_TYPE, JackPortIsInput, 0);
    if (p == nullptr) {
      jack_client_close(client_);
      throw std::runtime_error("JackRecorder: cannot register port " + port);
    }
    ports_.push_back(p);
    buffers_.emplace_back(capacity_frames, 0.0f);
  }
  jack_set_process_callback(client_, &JackRecorder::process, this);
  jack_set_xrun_callback(client_, &JackRecorder::xrun, this);
  if (jack_activate(client_) != 0) {
    jack_client_close(client_);
    throw std::runtime_error("JackRecorder: cannot activate client '" + name + "'");
  }
}

JackRecorder::~JackRecorder() { jack_client_close(client_); }

std::string JackRecorder::port_name(std::size_t input) const {
  return name_ + ":in_" + std::to_string(input + 1);
}

bool JackRecorder::connect(const std::string& source, std::size_t input) {
  return connect_ports(source, port_name(input));
}

bool JackRecorder::connect_ports(const std::string& source, const std::string& destination) {
  return jack_connect(client_, source.c_str(), destination.c_str()) == 0;
}

bool JackRecorder::wait_full(std::chrono::milliseconds timeout) const {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (recorded() < capacity_) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return true;
}

int JackRecorder::process(jack_nframes_t frames, void* self) noexcept {
  auto& r = *static_cast<JackRecorder*>(self);
  bool nonsilent = false;
  const bool recording = r.recording_.load(std::memory_order_acquire);
  const std::size_t at = r.recorded_.load(std::memory_order_relaxed);
  const std::size_t n = recording ? std::min<std::size_t>(frames, r.capacity_ - at) : 0;
  const std::size_t cycle = r.cycle_count_.load(std::memory_order_relaxed);
  if (n > 0 && cycle < r.cycles_.size()) {
    jack_nframes_t first = 0;
    jack_time_t started = 0, next = 0;
    float period = 0.0f;
    jack_get_cycle_times(r.client_, &first, &started, &next, &period);
    timespec now{};
    clock_gettime(CLOCK_MONOTONIC, &now);
    const double heard_s =
        static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
    r.cycles_[cycle] = Cycle{jack_last_frame_time(r.client_), at, n, started, heard_s};
    r.cycle_count_.store(cycle + 1, std::memory_order_release);
  }
  for (std::size_t i = 0; i < r.ports_.size(); ++i) {
    const auto* in = static_cast<const float*>(jack_port_get_buffer(r.ports_[i], frames));
    nonsilent = nonsilent || std::any_of(in, in + frames, [](float x) { return x != 0.0f; });
    std::copy_n(in, n, r.buffers_[i].data() + at);
  }
  if (nonsilent) r.nonsilent_.fetch_add(frames, std::memory_order_release);
  if (n > 0) r.recorded_.store(at + n, std::memory_order_release);
  return 0;
}

int JackRecorder::xrun(void* self) noexcept {
  static_cast<JackRecorder*>(self)->xruns_.fetch_add(1, std::memory_order_release);
  return 0;
}

}  // namespace nibrig::playback::testing
