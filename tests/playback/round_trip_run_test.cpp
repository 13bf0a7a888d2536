// The round trip measured on a real JACK server whose output is patched back to its input, checked
// against the latency JACK reports for the path plus the one period RtAudio's JACK back end holds
// the input back (recipes: RtAudio hands its callback input one period old), and the cycle a loop
// through other clients costs.
#include "playback/round_trip_run.hpp"

#include <gtest/gtest.h>
#include <jack/jack.h>

#include <chrono>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "tests/playback/jack_stream_settings.hpp"
#include "tests/support/jack_server.hpp"

namespace nibrig::playback {
namespace {

// A bare libjack client that wires the graph and reads the latencies JACK reports on it.
class RoundTripPatchbay {
 public:
  RoundTripPatchbay() {
    jack_status_t status{};
    client_ = jack_client_open("round-trip-patchbay", JackNoStartServer, &status);
    if (client_ == nullptr) throw std::runtime_error("round trip test: cannot open a JACK client");
  }
  ~RoundTripPatchbay() { jack_client_close(client_); }
  RoundTripPatchbay(const RoundTripPatchbay&) = delete;
  RoundTripPatchbay& operator=(const RoundTripPatchbay&) = delete;

  void connect(const std::string& from, const std::string& to) {
    if (jack_connect(client_, from.c_str(), to.c_str()) != 0)
      throw std::runtime_error("round trip test: cannot connect '" + from + "' to '" + to + "'");
  }
  // The port's latency range in one direction; throws when the port is not there.
  jack_latency_range_t latency(const std::string& port, jack_latency_callback_mode_t mode) {
    jack_port_t* p = jack_port_by_name(client_, port.c_str());
    if (p == nullptr) throw std::runtime_error("round trip test: no JACK port '" + port + "'");
    jack_latency_range_t range{};
    jack_port_get_latency_range(p, mode, &range);
    return range;
  }

 private:
  jack_client_t* client_ = nullptr;
};

// A JACK client that delays its input by a fixed number of frames and declares that latency on its
// ports through JACK's latency callback, as a plugin host or a network bridge does: hardware in the
// path that this machine does not have, whose latency JACK then reports.
class RoundTripDelayLine {
 public:
  explicit RoundTripDelayLine(std::size_t frames) : line_(frames, 0.0f) {
    jack_status_t status{};
    client_ = jack_client_open("round-trip-delay", JackNoStartServer, &status);
    if (client_ == nullptr)
      throw std::runtime_error("round trip test: cannot open the delay client");
    in_ = jack_port_register(client_, "in", JACK_DEFAULT_AUDIO_TYPE, JackPortIsInput, 0);
    out_ = jack_port_register(client_, "out", JACK_DEFAULT_AUDIO_TYPE, JackPortIsOutput, 0);
    if (in_ == nullptr || out_ == nullptr ||
        jack_set_process_callback(client_, &process, this) != 0 ||
        jack_set_latency_callback(client_, &latency, this) != 0 || jack_activate(client_) != 0) {
      jack_client_close(client_);
      throw std::runtime_error("round trip test: cannot set the delay client up");
    }
  }
  ~RoundTripDelayLine() { jack_client_close(client_); }
  RoundTripDelayLine(const RoundTripDelayLine&) = delete;
  RoundTripDelayLine& operator=(const RoundTripDelayLine&) = delete;

 private:
  static int process(jack_nframes_t frames, void* self) noexcept {
    auto& d = *static_cast<RoundTripDelayLine*>(self);
    const auto* in = static_cast<const float*>(jack_port_get_buffer(d.in_, frames));
    auto* out = static_cast<float*>(jack_port_get_buffer(d.out_, frames));
    for (jack_nframes_t i = 0; i < frames; ++i) {
      out[i] = d.line_[d.at_];
      d.line_[d.at_] = in[i];
      d.at_ = (d.at_ + 1) % d.line_.size();
    }
    return 0;
  }
  // What arrives at `out` was captured the delay earlier than at `in`; what enters `in` is played
  // the delay later than what leaves `out`.
  static void latency(jack_latency_callback_mode_t mode, void* self) noexcept {
    auto& d = *static_cast<RoundTripDelayLine*>(self);
    const auto delay = static_cast<jack_nframes_t>(d.line_.size());
    jack_latency_range_t range{};
    if (mode == JackCaptureLatency) {
      jack_port_get_latency_range(d.in_, mode, &range);
      range.min += delay;
      range.max += delay;
      jack_port_set_latency_range(d.out_, mode, &range);
    } else {
      jack_port_get_latency_range(d.out_, mode, &range);
      range.min += delay;
      range.max += delay;
      jack_port_set_latency_range(d.in_, mode, &range);
    }
  }

  std::vector<float> line_;
  std::size_t at_ = 0;
  jack_client_t* client_ = nullptr;
  jack_port_t* in_ = nullptr;
  jack_port_t* out_ = nullptr;
};

RoundTripSettings round_trip_on_jack(const std::string& stream) {
  RoundTripSettings settings;
  settings.device = testing::jack_settings(stream);
  settings.device.input_channel = 1;
  settings.impulses = 20;
  settings.interval_s = 0.1;
  return settings;
}

// Every impulse must be found at `expected` frames. The path is digital and JACK's frame clock
// exact, so the tolerance is zero samples, and a found impulse is a scaled copy: its correlation
// is 1 but for float rounding. Only an xrun may move or spoil a block (JACK then hands it a cycle
// late, half written or as silence: audio_output_loopback_test), so with xruns reported up to
// 10 % of the impulses may be missing, and up to 10 % of those found late or partly overwritten.
void expect_round_trip(const RoundTripResult& r, long expected, int period) {
  SCOPED_TRACE(::testing::Message()
               << "period " << period << ": found " << r.stats.found << " of " << r.stats.played
               << ", mean " << r.stats.mean_samples << ", worst " << r.stats.worst_samples
               << ", expected " << expected << "; " << r.xruns << " xruns");
  EXPECT_EQ(r.stream.period_frames, static_cast<unsigned>(period));
  ASSERT_GT(r.stats.played, 0u);
  std::size_t clean = 0;
  for (const auto& found : r.impulses) {
    if (!found) continue;
    const long lag = static_cast<long>(found->lag_samples);
    EXPECT_LE(std::abs(lag - expected), period);
    if (lag == expected && found->correlation > 0.999) ++clean;
  }
  if (r.xruns == 0) {
    EXPECT_EQ(r.stats.found, r.stats.played);
    EXPECT_EQ(clean, r.stats.found);
    EXPECT_EQ(r.stats.stddev_samples, 0.0);
    const double ms = 1e3 * static_cast<double>(expected) / r.stream.sample_rate;
    EXPECT_NEAR(r.mean_ms, ms, 1e-9);
  } else {
    EXPECT_GE(r.stats.found * 10, r.stats.played * 9);
    EXPECT_GE(clean * 10, r.stats.found * 9);
  }
}

class RoundTripOnJack : public ::testing::TestWithParam<int> {};

// The stream's output port patched straight to its input port: JACK reports the latency of both
// ports on that path, and RtAudio adds its period.
TEST_P(RoundTripOnJack, OutputPatchedToInputMeasuresJacksReportPlusRtAudiosPeriod) {
  const int period = GetParam();
  nibrig::testing::JackServer server({48000, period, 0});
  RoundTripPatchbay patchbay;
  const std::string stream = "round-trip-" + std::to_string(period);
  RoundTripSettings settings = round_trip_on_jack(stream);
  long reported_min = -1, reported_max = -1;
  settings.on_open = [&](const StreamInfo&) {
    patchbay.connect(stream + ":outport 0", stream + ":inport 0");
    const auto out = patchbay.latency(stream + ":outport 0", JackPlaybackLatency);
    const auto in = patchbay.latency(stream + ":inport 0", JackCaptureLatency);
    reported_min = static_cast<long>(out.min + in.min);
    reported_max = static_cast<long>(out.max + in.max);
  };
  const auto results = measure_round_trips(settings, {static_cast<unsigned>(period)});
  ASSERT_EQ(results.size(), 1u);
  ::testing::Test::RecordProperty("jack_reported_frames", std::to_string(reported_max));
  ::testing::Test::RecordProperty("mean_frames", std::to_string(results[0].stats.mean_samples));
  // The two ends of a range agree, or "what JACK reports" would be a span, not one figure.
  ASSERT_EQ(reported_min, reported_max);
  expect_round_trip(results[0], reported_max + period, period);
}

// Through a client that delays by 100 frames (not a whole number of periods) and declares it, as a
// plugin host does: JACK reports those 100 frames across its ports. A loop of clients has one
// connection JACK delivers a cycle late (the stream runs before the delay that feeds it back), a
// period JACK's latencies leave out; RtAudio adds its own. The round trip is the report plus two
// periods, to the sample.
TEST_P(RoundTripOnJack, ThroughADelayThatDeclaresItsLatencyMeasuresJacksReportPlusRtAudiosPeriod) {
  const int period = GetParam();
  nibrig::testing::JackServer server({48000, period, 0});
  RoundTripPatchbay patchbay;
  RoundTripDelayLine delay(100);
  const std::string stream = "round-trip-delay-" + std::to_string(period);
  RoundTripSettings settings = round_trip_on_jack(stream);
  long reported_min = -1, reported_max = -1;
  settings.on_open = [&](const StreamInfo&) {
    patchbay.connect(stream + ":outport 0", "round-trip-delay:in");
    patchbay.connect("round-trip-delay:out", stream + ":inport 0");
    // The loop feeds the stream's inputs back to its outputs in JACK's default latency
    // propagation, so the ports' capture latencies grow with each pass; what the path adds between
    // the stream's ports is the difference across it. Read until two reads 20 ms apart agree, as
    // a pass may land between the two ports' reads.
    for (int attempt = 0; attempt < 50; ++attempt) {
      const auto out = patchbay.latency("round-trip-delay:out", JackCaptureLatency);
      const auto in = patchbay.latency("round-trip-delay:in", JackCaptureLatency);
      const long min = static_cast<long>(out.min) - static_cast<long>(in.min);
      const long max = static_cast<long>(out.max) - static_cast<long>(in.max);
      if (min == reported_min && max == reported_max) break;
      reported_min = min;
      reported_max = max;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  };
  const auto results = measure_round_trips(settings, {static_cast<unsigned>(period)});
  ASSERT_EQ(results.size(), 1u);
  ::testing::Test::RecordProperty("jack_reported_frames", std::to_string(reported_max));
  ::testing::Test::RecordProperty("mean_frames", std::to_string(results[0].stats.mean_samples));
  ASSERT_EQ(reported_min, reported_max);
  EXPECT_EQ(reported_max, 100);
  expect_round_trip(results[0], reported_max + 2L * period, period);
}

// Through JACK's loopback driver (jackd -L), which copies what its playback port received in one
// cycle to its capture port in the next: one period of its own. Its ports report the latencies of a
// sound card (capture one period, playback two in asynchronous mode), which that copy does not
// have; the test records them beside the measurement and checks the copy's one period.
TEST_P(RoundTripOnJack, ThroughJacksLoopbackDriverMeasuresItsCycleAndRtAudiosPeriod) {
  const int period = GetParam();
  nibrig::testing::JackServer server({48000, period, 1});
  RoundTripPatchbay patchbay;
  const std::string stream = "round-trip-loop-" + std::to_string(period);
  RoundTripSettings settings = round_trip_on_jack(stream);
  long reported = -1;
  settings.on_open = [&](const StreamInfo&) {
    patchbay.connect(stream + ":outport 0", "loopback:playback_1");
    patchbay.connect("loopback:capture_1", stream + ":inport 0");
    reported = static_cast<long>(patchbay.latency("loopback:playback_1", JackPlaybackLatency).max +
                                 patchbay.latency("loopback:capture_1", JackCaptureLatency).max);
  };
  const auto results = measure_round_trips(settings, {static_cast<unsigned>(period)});
  ASSERT_EQ(results.size(), 1u);
  ::testing::Test::RecordProperty("jack_reported_frames", std::to_string(reported));
  ::testing::Test::RecordProperty("mean_frames", std::to_string(results[0].stats.mean_samples));
  expect_round_trip(results[0], 2L * period, period);
}

// The input taken from another device by name: the stream plays to `system` and records from
// `loopback` (RtAudio lists each JACK client with physical ports as a device and connects the
// stream to the ones named); the test adds the one patch from the output to the loopback, so the
// impulses can only come back through the input device named.
TEST(RoundTripOnJackDevices, RecordsFromTheInputDeviceNamed) {
  nibrig::testing::JackServer server({48000, 64, 1});
  RoundTripPatchbay patchbay;
  RoundTripSettings settings = round_trip_on_jack("round-trip-devices");
  settings.device.connect_ports = true;
  settings.device.input_device = "loop";  // a unique part of the name, as for `device`
  settings.impulses = 5;
  std::string input_device;
  settings.on_open = [&](const StreamInfo& info) {
    input_device = info.input_device;
    patchbay.connect("round-trip-devices:outport 0", "loopback:playback_1");
  };
  const auto results = measure_round_trips(settings);
  ASSERT_EQ(results.size(), 1u);
  EXPECT_EQ(results[0].stream.device, "system");
  EXPECT_EQ(input_device, "loopback");
  EXPECT_EQ(results[0].stream.input_device, "loopback");
  expect_round_trip(results[0], 2L * 64, 64);
}

INSTANTIATE_TEST_SUITE_P(Periods, RoundTripOnJack, ::testing::Values(64, 256),
                         [](const auto& info) { return "period" + std::to_string(info.param); });

}  // namespace
}  // namespace nibrig::playback
