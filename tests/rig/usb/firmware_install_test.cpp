// `cmake --install` of a tree that built the firmware puts the hex `nibrig rig flash` writes in
// share/nibrig/firmware (rig/usb/firmware_flash.hpp finds it there for an installed nibrig).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "tests/support/run_program.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::rig::usb {
namespace {

namespace fs = std::filesystem;

std::string bytes_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(FirmwareInstall, TheInstalledHexIsTheOneBuilt) {
#ifndef NIBRIG_FIRMWARE_ELF
  GTEST_SKIP() << "a tree without the firmware (-DNIBRIG_BUILD_FIRMWARE=OFF)";
#else
  const fs::path built = fs::path(NIBRIG_FIRMWARE_ELF).replace_extension(".hex");
  ASSERT_TRUE(fs::is_regular_file(built)) << built;
  const auto scratch = nibrig::test::scratch_dir("firmware_install");
  const auto build = fs::path(NIBRIG_TEST_BINARY_DIR).parent_path();
  const auto run = nibrig::test::run_program({"cmake", "--install", build.string(), "--prefix",
                                              (scratch / "usr").string(), "--component", "command"},
                                             scratch);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto installed = scratch / "usr" / "share" / "nibrig" / "firmware" / "nibrig-rig.hex";
  ASSERT_TRUE(fs::is_regular_file(installed)) << run.output;
  EXPECT_EQ(bytes_of(installed), bytes_of(built));
#endif
}

}  // namespace
}  // namespace nibrig::rig::usb
