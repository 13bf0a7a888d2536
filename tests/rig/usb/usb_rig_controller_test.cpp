// The libusb driver against the emulated rig controller (emulated_rig.hpp): real libusb, real usbfs
// ioctls answered by a device that follows PROTOCOL.md, faults on demand.
#include "rig/usb/usb_rig_controller.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>
#include <vector>

#include "rig/usb/usb_rig_error.hpp"
#include "tests/rig/usb/emulated_rig.hpp"

namespace nibrig::rig::usb {
namespace {

using namespace std::chrono_literals;
using testing::EmulatedRig;
using testing::EmulatedRigConfig;
using testing::Testbed;

// Drains the controller for `duration`, as a consumer thread would.
std::vector<SensorFrame> drain_for(UsbRigController& rig, std::chrono::milliseconds duration) {
  std::vector<SensorFrame> frames;
  std::vector<SensorFrame> block(256);
  const auto end = std::chrono::steady_clock::now() + duration;
  while (std::chrono::steady_clock::now() < end) {
    const std::size_t n = rig.read_frames(block);
    frames.insert(frames.end(), block.begin(), block.begin() + static_cast<std::ptrdiff_t>(n));
    std::this_thread::sleep_for(2ms);
  }
  return frames;
}

// Waits until `condition` holds or `limit` passes; true when it held.
template <typename F>
bool eventually(F condition, std::chrono::milliseconds limit = 3000ms) {
  const auto end = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < end) {
    if (condition()) return true;
    std::this_thread::sleep_for(5ms);
  }
  return condition();
}

TEST(UsbRigController, IdentifiesTheEmulatedDevice) {
  Testbed testbed;
  EmulatedRig device(testbed.get(), EmulatedRigConfig{});
  UsbRigController rig;
  const Identity id = rig.identify();
  EXPECT_EQ(id.serial, "NIB-0001");
  EXPECT_EQ(id.protocol_version, kProtocolVersion);
  EXPECT_NEAR(id.max_speed_m_s, 0.3, 1e-6);  // f32 of 300 mm/s
  EXPECT_EQ(id.frame_rate_hz, 1000u);
  EXPECT_EQ(id.watchdog_timeout_ms, 500u);
  EXPECT_TRUE(rig.status().connected);
}

TEST(UsbRigController, StreamsEverySequenceNumberAtOneKilohertz) {
  Testbed testbed;
  EmulatedRig device(testbed.get(), EmulatedRigConfig{});
  UsbRigController rig;
  const auto frames = drain_for(rig, 1000ms);
  // ~1000 frames in 1 s; at least 800 allows a loaded 2-core machine's scheduling slack.
  ASSERT_GE(frames.size(), 800u);
  for (std::size_t i = 1; i < frames.size(); ++i) {
    ASSERT_EQ(frames[i].sequence, frames[i - 1].sequence + 1) << "at frame " << i;
    // The device clock ticks 1000 us a frame at 1 kHz.
    ASSERT_EQ(frames[i].device_time_us - frames[i - 1].device_time_us, 1000u) << "at frame " << i;
  }
  const UsbRigStatus s = rig.status();
  EXPECT_EQ(s.frames_dropped, 0u);
  EXPECT_EQ(s.frames_reordered, 0u);
  EXPECT_EQ(s.frames_received, frames.size());
  EXPECT_EQ(frames.front().sequence, device.first_streamed_sequence());
}

}  // namespace
}  // namespace nibrig::rig::usb
