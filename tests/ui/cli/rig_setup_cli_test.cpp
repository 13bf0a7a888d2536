// `nibrig rig calibrate` and `nibrig rig flash` from the command line: what they refuse before
// touching a device, in one clear line (their work is tested against the emulated controller and
// the real avrdude in tests/rig/usb).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/ui/cli/cli_harness.hpp"

namespace nibrig::test {
namespace {

TEST(RigSetupCli, BadRequestsGetOneClearLine) {
  struct Case {
    std::vector<std::string> args;
    int code;
    std::string says;
  };
  const std::vector<Case> cases = {
      {{"rig", "calibrate"}, 2, "nothing to do: give --zero, --normal-weight"},
      {{"rig", "calibrate", "--normal-weight", "200"}, 2,
       "--normal-weight '200': expected a weight above 0 with its unit, in grams, kilograms or newtons"},
      {{"rig", "calibrate", "--serial", "LAB 7"}, 2, "character 4 of the serial is byte 0x20"},
      {{"rig", "calibrate", "--radius", "0"}, 2, "--radius"},
      // No controller on this machine's bus: the line says what was looked for.
      {{"rig", "calibrate", "--zero", "--yes"}, 1, "no nibrig rig controller (USB 1209:000a) on the bus"},
      {{"rig", "flash", "--hex", "/nonexistent/nibrig-rig.hex"}, 1, "--hex /nonexistent/nibrig-rig.hex: no such file"},
  };
  for (const auto& c : cases) {
    ::testing::internal::CaptureStderr();
    const int code = run_cli(c.args);
    const std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_EQ(code, c.code) << c.args[2] << ": " << err;
    EXPECT_NE(err.find(c.says), std::string::npos) << err;
  }
}

}  // namespace
}  // namespace nibrig::test
