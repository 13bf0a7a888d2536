// What a person at the rig reads when the firmware stops the motor: the real firmware on the
// simulated board, the real libusb driver, the cause carried by GET_STATUS (PROTOCOL.md 1.2) into
// the controller's status with what to check, and gone again with the next start.
#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <thread>

#include "rig/usb/usb_rig_controller.hpp"
#include "tests/rig/usb/emulated_rig.hpp"
#ifdef NIBRIG_FIRMWARE_ELF
#include "tests/rig/usb/firmware_rig.hpp"
#endif

namespace nibrig::rig::usb {
namespace {

#ifdef NIBRIG_FIRMWARE_ELF
using namespace std::chrono_literals;

// The device's fault as the controller last read it, waiting up to `limit` for one.
std::string fault_report_within(const UsbRigController& rig, std::chrono::milliseconds limit) {
  const auto until = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < until) {
    const std::string fault = rig.status().device_fault;
    if (!fault.empty()) return fault;
    std::this_thread::sleep_for(10ms);
  }
  return "";
}

TEST(FirmwareFaultReport, AReversedEncoderReachesTheHostWithWhatToCheck) {
  testing::Testbed testbed;
  testing::TurntablePhysics physics;
  physics.encoder_reversed = true;
  testing::FirmwareRig device(testbed.get(), testing::EmulatedRigConfig{}, physics);
  UsbRigController rig;
  rig.set_speed(0.1);
  // The stop within 0.1 s, then the keep-alive's next GET_STATUS (every 133 ms); 2 s for a loaded
  // machine running the chip in real time.
  const std::string fault = fault_report_within(rig, 2000ms);
  EXPECT_NE(fault.find("stopped the motor: encoder reversed"), std::string::npos) << fault;
  EXPECT_NE(fault.find("swap encoder A and B (yellow and white)"), std::string::npos) << fault;
  EXPECT_EQ(device.status().fault, Fault::kEncoder);
  // The next start clears it on both sides (the firmware stops again: the wiring is as it was).
  rig.set_speed(0.05);
  EXPECT_EQ(rig.status().device_fault, "");
}
#endif

}  // namespace
}  // namespace nibrig::rig::usb
