// The accelerometer path through a real JACK server: a JACK client plays a known signal into the
// capture stream's input port, as an accelerometer on an interface input would.
#include "rig/accelerometer_input.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>

#include "playback/device_error.hpp"
#include "tests/rig/jack_feeder.hpp"
#include "tests/support/jack_server.hpp"

namespace nibrig::rig {
namespace {

AccelerometerSettings jack_input(const std::string& stream) {
  AccelerometerSettings s;
  s.stream.api = "jack";
  s.stream.stream_name = stream;
  s.stream.connect_ports = false;  // the test patches the feeder in itself
  s.stream.period_frames = 64;
  // The feeder plays straight into the stream's port: no converter delays it (the back end's
  // latency is system:capture's).
  s.device_latency_s = 0.0;
  return s;
}

// The captured samples are what was played, in full-scale units (the scale to m/s² is the
// session's calibration): a 0.5 full-scale sine reads 0.5. And the clock puts the captured impulse
// on the host clock within 2 ms (the whole rig's goal) of when JACK says it was in the graph — the
// accelerometer's half of the rig's time base.
TEST(AccelerometerInput, CapturesWhatJackPlaysAndTimesItOnTheHostClock) {
  nibrig::testing::JackServer server;
  testing::JackFeeder feeder("feeder", 0.5, 440.0);
  AccelerometerInput input(jack_input("accel"));
  ASSERT_TRUE(feeder.connect("accel:inport 0"));
  // JACK's clock (jack_get_time) is CLOCK_MONOTONIC_RAW here, the stamps' the steady clock
  // (CLOCK_MONOTONIC): they differ by an offset that moves only with the clock's slewing. It is
  // read back to back before and after, and the truth taken over with their mean.
  const auto steady_minus_jack = [&] {
    const double jack = feeder.now_us() * 1e-6;
    const double steady =
        std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
    return steady - jack;
  };
  const double offset_before = steady_minus_jack();
  std::vector<float> captured;
  // As a capture does: each sample is put on the host clock when it is read, with the clock as it
  // stands then.
  std::size_t at = 0;
  double estimate = 0.0;
  const auto run = [&](double seconds) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < until) {
      const std::size_t before = captured.size();
      input.read(captured);
      for (std::size_t i = before; i < captured.size(); ++i) {
        if (captured[i] > 0.9f && at == 0) {  // the impulse: the sine never exceeds 0.5
          at = i;
          estimate = input.host_time_of(static_cast<double>(i));
        }
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  };
  run(2.5);
  feeder.impulse();
  run(0.5);
  ASSERT_GT(captured.size(), 2u * 48000u);
  ASSERT_GT(at, 0u) << "the impulse was not captured";
  // The sine's amplitude away from the impulse.
  float peak = 0.0f;
  for (std::size_t i = 0; i < captured.size(); ++i)
    if (i + 64 < at || i > at + 64) peak = std::max(peak, std::abs(captured[i]));
  EXPECT_NEAR(peak, 0.5f, 0.002f);  // 440 Hz at 48 kHz: a sample within 1.5 % of every crest

  ASSERT_NE(feeder.impulse_frame(), 0u);
  const double offset_after = steady_minus_jack();
  EXPECT_NEAR(offset_after, offset_before, 1e-3);  // the two clocks kept their offset
  const double jack_truth = feeder.frames_to_time_us(feeder.impulse_frame()) * 1e-6 +
                       (offset_before + offset_after) / 2.0;
  const double truth = feeder.impulse_host_s();
  RecordProperty("jack_dll_vs_callback_ms", std::to_string((jack_truth - truth) * 1e3));
  RecordProperty("impulse_error_ms", std::to_string((estimate - truth) * 1e3));
  RecordProperty("stamp_minus_truth_ms", std::to_string((estimate + input.buffering_s() - truth) * 1e3));
  RecordProperty("drift_ppm", std::to_string(input.clock().drift_ppm()));
  RecordProperty("buffering_ms", std::to_string(input.buffering_s() * 1e3));
  RecordProperty("device_latency_ms", std::to_string(input.device_latency_s() * 1e3));
  RecordProperty("residual_ms", std::to_string(input.clock().residual_s() * 1e3));
  EXPECT_NEAR(estimate, truth, 0.002);
}

TEST(AccelerometerInput, AMissingDeviceIsNamedWithWhatExists) {
  nibrig::testing::JackServer server;
  AccelerometerSettings s = jack_input("accel-missing");
  s.stream.device = "Scarlett";
  try {
    AccelerometerInput input(s);
    FAIL() << "a device that is not there was opened";
  } catch (const playback::DeviceError& e) {
    EXPECT_NE(std::string(e.what()).find("Scarlett"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("system"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace nibrig::rig
