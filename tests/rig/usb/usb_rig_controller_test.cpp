// The libusb driver against the rig controller: real libusb, real usbfs ioctls, answered by the
// emulated device (emulated_rig.hpp) and by the real firmware on the simulated board
// (firmware_rig.hpp). Each typed test runs against both; the emulator's own tests (injected
// refusals, other protocol versions) only against it.
#include "rig/usb/usb_rig_controller.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

#include "rig/usb/usb_rig_error.hpp"
#include "tests/rig/usb/emulated_rig.hpp"
#ifdef NIBRIG_FIRMWARE_ELF
#include "tests/rig/usb/firmware_rig.hpp"
#endif

namespace nibrig::rig::usb {
namespace {

using namespace std::chrono_literals;
using testing::EmulatedRig;
using testing::EmulatedRigConfig;
using testing::Testbed;

// What the two devices are built to do differently.
template <typename Device>
struct Design;
template <>
struct Design<EmulatedRig> {
  static constexpr std::uint16_t kProtocol = kProtocolVersion;
  static constexpr const char* kRates = "500 to 4000 Hz";
  static constexpr bool kBuffersSeconds = true;  // holds 8 s of frames while the host does not read
  static constexpr unsigned kWatchdogMs = 500;
};
#ifdef NIBRIG_FIRMWARE_ELF
template <>
struct Design<testing::FirmwareRig> {
  static constexpr std::uint16_t kProtocol = kProtocolVersion;  // the firmware's own
  static constexpr const char* kRates = "1000 to 3000 Hz";
  static constexpr bool kBuffersSeconds = false;  // the ATmega32U4's RAM holds 16 frames
  static constexpr unsigned kWatchdogMs = 400;    // RIG_WATCHDOG_MS: stopped, braked, within 600 ms
};
#endif

template <typename Device>
class UsbRigControllerOn : public ::testing::Test {};
struct DeviceName {
  template <typename Device>
  static std::string GetName(int) {
    return std::is_same_v<Device, EmulatedRig> ? "Emulator" : "Firmware";
  }
};
#ifdef NIBRIG_FIRMWARE_ELF
using Devices = ::testing::Types<EmulatedRig, testing::FirmwareRig>;
#else
using Devices = ::testing::Types<EmulatedRig>;
#endif
TYPED_TEST_SUITE(UsbRigControllerOn, Devices, DeviceName);

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

// The message of a UsbRigError thrown by `f`, or "" when nothing was thrown.
template <typename F>
std::string error_of(F f) {
  try {
    f();
  } catch (const UsbRigError& e) {
    return e.what();
  }
  return "";
}

TYPED_TEST(UsbRigControllerOn, IdentifiesTheDevice) {
  Testbed testbed;
  TypeParam device(testbed.get(), EmulatedRigConfig{});
  UsbRigController rig;
  const Identity id = rig.identify();
  EXPECT_EQ(id.serial, "NIB-0001");
  EXPECT_EQ(id.protocol_version, Design<TypeParam>::kProtocol);
  EXPECT_NEAR(id.max_speed_m_s, 0.3, 1e-6);  // f32 of 300 mm/s
  EXPECT_EQ(id.frame_rate_hz, 1000u);
  EXPECT_EQ(id.watchdog_timeout_ms, Design<TypeParam>::kWatchdogMs);
  EXPECT_TRUE(rig.status().connected);
}

TYPED_TEST(UsbRigControllerOn, StreamsEverySequenceNumberAtOneKilohertz) {
  Testbed testbed;
  TypeParam device(testbed.get(), EmulatedRigConfig{});
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
  // The stream runs on while we look: the count lies between what was drained before the snapshot
  // and that plus what is still queued after it.
  const std::size_t drained = frames.size();
  const auto rest = drain_for(rig, 20ms);
  EXPECT_GE(s.frames_received, drained);
  EXPECT_LE(s.frames_received, drained + rest.size());
  EXPECT_EQ(frames.front().sequence, device.first_streamed_sequence());
}


TEST(UsbRigController, ListsEveryControllerWithSerialBusAndVersion) {
  Testbed testbed;
  EmulatedRig a(testbed.get(), EmulatedRigConfig{"NIB-A", 2});
  EmulatedRig b(testbed.get(), EmulatedRigConfig{"NIB-B", 3});
  auto found = list_rig_controllers();
  ASSERT_EQ(found.size(), 2u);
  std::sort(found.begin(), found.end(), [](auto& x, auto& y) { return x.address < y.address; });
  EXPECT_EQ(found[0].serial, "NIB-A");
  EXPECT_EQ(found[0].bus, 1);
  EXPECT_EQ(found[0].address, 2);
  EXPECT_EQ(found[0].protocol_version, kProtocolVersion);
  EXPECT_EQ(found[0].problem, "");
  EXPECT_EQ(found[1].serial, "NIB-B");
  EXPECT_EQ(found[1].address, 3);
  EXPECT_EQ(describe(found[1]), "NIB-B (bus 1, address 3, protocol 1.2, firmware emulated-1.2)");
}

TEST(UsbRigController, AMissingDeviceSaysWhatIsThere) {
  {
    Testbed testbed;
    EXPECT_EQ(error_of([] { UsbRigController rig; }),
              "no nibrig rig controller (USB 1209:000a) on the bus");
  }
  Testbed testbed;
  EmulatedRig a(testbed.get(), EmulatedRigConfig{"NIB-A", 2});
  const std::string message = error_of([] { UsbRigController rig({.serial = "NIB-X"}); });
  EXPECT_EQ(message,
            "no nibrig rig controller (USB 1209:000a) with serial NIB-X; found: NIB-A (bus 1, "
            "address 2, protocol 1.2, firmware emulated-1.2)");
}

TYPED_TEST(UsbRigControllerOn, OpensTheOneWithTheSerialAskedFor) {
  Testbed testbed;
  TypeParam a(testbed.get(), EmulatedRigConfig{"NIB-A", 2});
  TypeParam b(testbed.get(), EmulatedRigConfig{"NIB-B", 3});
  {
    UsbRigController rig({.serial = "NIB-B"});
    EXPECT_EQ(rig.identity().serial, "NIB-B");
    rig.set_speed(0.1);
    // The request went to B, not A.
    EXPECT_NEAR(b.status().speed_target_m_s, 0.1, 1e-6);
    EXPECT_EQ(a.status().speed_target_m_s, 0.0);
  }
  // Two and no serial: which one is meant cannot be guessed.
  const std::string message = error_of([] { UsbRigController rig; });
  EXPECT_NE(message.find("several nibrig rig controllers are plugged in"), std::string::npos) << message;
  EXPECT_NE(message.find("NIB-A"), std::string::npos) << message;
  EXPECT_NE(message.find("NIB-B"), std::string::npos) << message;
}

TEST(UsbRigController, RefusesAnotherMajorProtocolVersionNamingBoth) {
  Testbed testbed;
  EmulatedRigConfig config;
  config.protocol_version = 0x0203;
  EmulatedRig device(testbed.get(), config);
  const std::string message = error_of([] { UsbRigController rig; });
  EXPECT_NE(message.find("speaks protocol 2.3; this nibrig speaks 1.x"), std::string::npos) << message;
}

TYPED_TEST(UsbRigControllerOn, UploadsAProfileInChunksAndReadsItBack) {
  Testbed testbed;
  TypeParam device(testbed.get(), EmulatedRigConfig{});
  UsbRigController rig;
  const SpeedProfile steps = paper_steps();  // 13 points per sweep: two chunks of 8
  ASSERT_GT(steps.points().size(), kMaxPointsPerRequest);
  rig.upload_profile(steps);
  const auto back = rig.read_profile();
  const auto held = device.held_profile();
  ASSERT_EQ(back.size(), steps.points().size());
  ASSERT_EQ(held.size(), steps.points().size());
  for (std::size_t i = 0; i < back.size(); ++i) {
    // Times travel in whole milliseconds, speeds as f32 mm/s (PROTOCOL.md "Profile").
    EXPECT_NEAR(back[i].time_s, steps.points()[i].time_s, 0.0005) << i;
    EXPECT_NEAR(back[i].speed_m_s, steps.points()[i].speed_m_s, 1e-7) << i;
    EXPECT_EQ(held[i].time_s, back[i].time_s) << i;
  }
  rig.start_profile();
  EXPECT_EQ(device.status().mode, Mode::kProfile);
  rig.stop();
  EXPECT_EQ(device.status().mode, Mode::kIdle);
}

TYPED_TEST(UsbRigControllerOn, RefusesAProfileBeyondTheMotorStatingTheRange) {
  Testbed testbed;
  TypeParam device(testbed.get(), EmulatedRigConfig{});
  UsbRigController rig;
  const SpeedProfile fast("too fast", {{0.0, 0.0}, {1.0, 0.4}});
  EXPECT_EQ(error_of([&] { rig.upload_profile(fast); }),
            "profile 'too fast' reaches 400.0 mm/s; the rig controller NIB-0001 runs 0 to 300.0 mm/s");
  EXPECT_EQ(device.status().profile_points, 0);  // nothing was sent
  EXPECT_EQ(error_of([&] { rig.set_speed(0.5); }),
            "speed 500.0 mm/s is outside what the rig controller NIB-0001 runs: 0 to 300.0 mm/s");
}

TYPED_TEST(UsbRigControllerOn, CalibrationFrameRateAndZeroReachTheDevice) {
  Testbed testbed;
  TypeParam device(testbed.get(), EmulatedRigConfig{});
  UsbRigController rig;
  // Another cell and lever, within what the firmware's 10-bit converter makes sense of (PROTOCOL.md).
  rig.set_calibration({64.0, 48.0, 1.5});
  const ForceCalibration c = rig.calibration();
  EXPECT_EQ(c.normal_counts_per_N, 64.0);  // exact in f32
  EXPECT_EQ(c.tangential_counts_per_N, 48.0);
  EXPECT_EQ(c.lever_factor, 1.5);
  EXPECT_EQ(device.calibration().lever_factor, 1.5);

  rig.set_frame_rate(2000);
  EXPECT_EQ(rig.identify().frame_rate_hz, 2000u);
  EXPECT_NE(error_of([&] { rig.set_frame_rate(100); }).find(Design<TypeParam>::kRates), std::string::npos);

  // Zeroing takes the arm's load as the zero: frames read ~0 N afterwards (exactly: the firmware's
  // zero and its frames average the same steady ADC counts).
  rig.zero_force();
  drain_for(rig, 50ms);  // frames sampled before the zero
  const auto frames = drain_for(rig, 100ms);
  ASSERT_FALSE(frames.empty());
  EXPECT_NEAR(frames.back().normal_force_N, 0.0f, 1e-6f);
}

TEST(UsbRigController, AStalledRequestSaysWhichAndWhy) {
  Testbed testbed;
  EmulatedRig device(testbed.get(), EmulatedRigConfig{});
  UsbRigController rig;
  device.refuse_next(Request::kZeroForce, Refusal::kOrder);
  EXPECT_EQ(error_of([&] { rig.zero_force(); }),
            "the rig controller NIB-0001 refused ZERO_FORCE (0x30) (STALL): out of order");
  // A refusal of the device's own (PROTOCOL.md: START_PROFILE without a profile), not injected.
  EXPECT_EQ(error_of([&] { rig.start_profile(); }),
            "the rig controller NIB-0001 refused START_PROFILE (0x11) (STALL): out of order");
  // Streaming went on through the refusals.
  EXPECT_TRUE(rig.status().connected);
  EXPECT_FALSE(drain_for(rig, 50ms).empty());
}

// PROTOCOL.md's own refusal, met by the device, not injected: START_PROFILE without a profile.
TYPED_TEST(UsbRigControllerOn, RefusesToStartWithoutAProfileSayingWhy) {
  Testbed testbed;
  TypeParam device(testbed.get(), EmulatedRigConfig{});
  UsbRigController rig;
  EXPECT_EQ(error_of([&] { rig.start_profile(); }),
            "the rig controller NIB-0001 refused START_PROFILE (0x11) (STALL): out of order");
  EXPECT_EQ(device.status().refused_request, 0x11);
  EXPECT_EQ(device.status().mode, Mode::kIdle);
  // The stream went on through the refusal.
  EXPECT_TRUE(rig.status().connected);
  EXPECT_FALSE(drain_for(rig, 50ms).empty());
}

TYPED_TEST(UsbRigControllerOn, AControlRequestWithoutAnswerTimesOut) {
  Testbed testbed;
  TypeParam device(testbed.get(), EmulatedRigConfig{});
  UsbRigController::Options options;
  options.control_timeout_ms = 200;
  UsbRigController rig(options);
  device.ignore_next_control();
  const auto start = std::chrono::steady_clock::now();
  const std::string message = error_of([&] { rig.stop(); });
  const auto waited = std::chrono::steady_clock::now() - start;
  EXPECT_EQ(message, "the rig controller NIB-0001 did not answer STOP (0x12) within 200 ms");
  // It gave up at its timeout, not much later (1 s allows a loaded machine).
  EXPECT_LT(waited, 1200ms);
  EXPECT_NO_THROW(rig.stop());  // the next one is answered
}

TYPED_TEST(UsbRigControllerOn, ASilentStreamTimesOutAndLosesNothing) {
  Testbed testbed;
  TypeParam device(testbed.get(), EmulatedRigConfig{});
  UsbRigController rig;
  drain_for(rig, 100ms);
  device.hold_stream(true);
  std::this_thread::sleep_for(400ms);  // transfers time out every 100 ms and go out again
  device.hold_stream(false);
  const auto frames = drain_for(rig, 300ms);
  const UsbRigStatus s = rig.status();
  EXPECT_GE(s.transfer_timeouts, 1u);
  ASSERT_FALSE(frames.empty());
  if constexpr (Design<TypeParam>::kBuffersSeconds) {
    // The device kept the frames sampled meanwhile (its buffer holds 8 s): none is lost.
    EXPECT_EQ(s.frames_dropped, 0u);
    for (std::size_t i = 1; i < frames.size(); ++i) ASSERT_EQ(frames[i].sequence, frames[i - 1].sequence + 1);
  } else {
    // The firmware's 16 frames overflowed: what it could not keep is counted as dropped, and the
    // frames delivered still rise one by one but for that gap.
    EXPECT_GE(s.frames_dropped, 300u);  // of ~400 sampled in the hold
    for (std::size_t i = 1; i < frames.size(); ++i) ASSERT_GT(frames[i].sequence, frames[i - 1].sequence);
  }
}

TYPED_TEST(UsbRigControllerOn, CountsDroppedReorderedAndDuplicatedFramesAndDeliversNoneTwice) {
  Testbed testbed;
  TypeParam device(testbed.get(), EmulatedRigConfig{});
  UsbRigController rig;
  auto frames = drain_for(rig, 100ms);
  device.drop_frames(5);
  auto more = drain_for(rig, 100ms);
  frames.insert(frames.end(), more.begin(), more.end());
  device.reorder_next_packet();
  more = drain_for(rig, 100ms);
  frames.insert(frames.end(), more.begin(), more.end());
  device.duplicate_next_packet();
  more = drain_for(rig, 100ms);
  frames.insert(frames.end(), more.begin(), more.end());
  const UsbRigStatus s = rig.status();
  EXPECT_EQ(s.frames_dropped, 5u);
  EXPECT_EQ(s.frames_reordered, 1u);  // the late one of the swapped pair
  ASSERT_GT(device.frames_duplicated(), 0u);
  EXPECT_EQ(s.frames_duplicated, device.frames_duplicated());
  ASSERT_GE(frames.size(), 2u);
  // Delivered frames rise strictly: none twice, none out of order; every number between the first
  // and the last is delivered, dropped or late.
  for (std::size_t i = 1; i < frames.size(); ++i) ASSERT_GT(frames[i].sequence, frames[i - 1].sequence);
  const std::uint64_t span = frames.back().sequence - frames.front().sequence + 1;
  EXPECT_EQ(span, frames.size() + s.frames_dropped + s.frames_reordered);
}

TYPED_TEST(UsbRigControllerOn, UnplugKeepsTheFramesAndReplugResumesStreaming) {
  Testbed testbed;
  TypeParam device(testbed.get(), EmulatedRigConfig{});
  UsbRigController rig;
  auto before = drain_for(rig, 200ms);
  ASSERT_GT(before.size(), 100u);

  device.unplug();
  ASSERT_TRUE(eventually([&] { return !rig.status().connected; }));
  const UsbRigStatus gone = rig.status();
  EXPECT_EQ(gone.disconnects, 1u);
  EXPECT_NE(gone.last_fault.find("was unplugged"), std::string::npos) << gone.last_fault;
  EXPECT_NE(error_of([&] { rig.stop(); }).find("is unplugged"), std::string::npos);
  // Every frame received before the unplug is still there for the consumer.
  const auto rest = drain_for(rig, 50ms);
  before.insert(before.end(), rest.begin(), rest.end());
  EXPECT_EQ(before.size(), gone.frames_received);

  device.replug(5);
  ASSERT_TRUE(eventually([&] { return rig.status().connected; }));
  EXPECT_EQ(rig.status().reconnects, 1u);
  EXPECT_NE(rig.status().last_fault.find("was unplugged"), std::string::npos);  // still told
  const auto after = drain_for(rig, 300ms);
  ASSERT_GT(after.size(), 100u);
  // The same device, its clock running on: the frames continue later in device time.
  EXPECT_GT(after.front().device_time_us, before.back().device_time_us);
  for (std::size_t i = 1; i < after.size(); ++i) ASSERT_EQ(after[i].sequence, after[i - 1].sequence + 1);
  EXPECT_EQ(rig.identify().serial, "NIB-0001");  // requests reach it again
}

TYPED_TEST(UsbRigControllerOn, ReconnectsOnlyToTheSameSerial) {
  Testbed testbed;
  TypeParam ours(testbed.get(), EmulatedRigConfig{"NIB-OURS", 2});
  UsbRigController rig;
  ours.unplug();
  ASSERT_TRUE(eventually([&] { return !rig.status().connected; }));
  // Another controller arrives: the rescan (every 200 ms) and its hotplug event must pass it by.
  TypeParam other(testbed.get(), EmulatedRigConfig{"NIB-OTHER", 3});
  std::this_thread::sleep_for(600ms);
  EXPECT_FALSE(rig.status().connected);
  EXPECT_EQ(rig.status().reconnects, 0u);
  ours.replug(4);
  ASSERT_TRUE(eventually([&] { return rig.status().connected; }));
  EXPECT_EQ(rig.identify().serial, "NIB-OURS");
}

TYPED_TEST(UsbRigControllerOn, TheWatchdogStopsTheMotorWhenTheHostIsSilent) {
  Testbed testbed;
  TypeParam device(testbed.get(), EmulatedRigConfig{});
  UsbRigController::Options options;
  options.keep_alive = false;  // the host falls silent
  UsbRigController rig(options);
  rig.set_speed(0.1);
  std::this_thread::sleep_for(800ms);  // silence beyond the 500 ms watchdog
  EXPECT_EQ(device.status().mode, Mode::kIdle);
  const auto frames = drain_for(rig, 50ms);
  ASSERT_FALSE(frames.empty());
  EXPECT_TRUE(frames.back().flags & kWatchdogStopped);
  const DeviceStatus s = rig.device_status();
  EXPECT_EQ(s.fault, Fault::kWatchdog);
}

TYPED_TEST(UsbRigControllerOn, TheKeepAliveHoldsTheWatchdogOff) {
  Testbed testbed;
  TypeParam device(testbed.get(), EmulatedRigConfig{});
  UsbRigController rig;
  rig.set_speed(0.1);
  std::this_thread::sleep_for(1200ms);  // over twice the watchdog's timeout, no call of ours
  EXPECT_EQ(device.status().mode, Mode::kSpeed);
  EXPECT_EQ(device.status().fault, Fault::kNone);
  const auto frames = drain_for(rig, 50ms);
  ASSERT_FALSE(frames.empty());
  EXPECT_FALSE(frames.back().flags & kWatchdogStopped);
  EXPECT_TRUE(frames.back().flags & kProfileRunning);
  // The motor followed its speed loop to the target (5 time constants of 50 ms and more).
  EXPECT_NEAR(frames.back().speed_m_s, 0.1f, 1e-3f);
}

TYPED_TEST(UsbRigControllerOn, ClosingStopsTheMotorAndTheStream) {
  Testbed testbed;
  TypeParam device(testbed.get(), EmulatedRigConfig{});
  {
    UsbRigController rig;
    rig.set_speed(0.2);
    EXPECT_EQ(device.status().mode, Mode::kSpeed);
    EXPECT_TRUE(device.streaming());
  }
  // At once, not after the watchdog's 500 ms.
  EXPECT_EQ(device.status().mode, Mode::kIdle);
  EXPECT_FALSE(device.streaming());
}

}  // namespace
}  // namespace nibrig::rig::usb
