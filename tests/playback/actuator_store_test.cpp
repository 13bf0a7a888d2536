#include "playback/actuator_store.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "tests/support/test_paths.hpp"

namespace nibrig::playback {
namespace {

TEST(ActuatorStore, OneFilePerActuatorNameFoundByNameOrPath) {
  const auto dir = nibrig::test::scratch_dir("actuator_store");
  ::setenv("NIBRIG_ACTUATORS", dir.c_str(), 1);
  EXPECT_EQ(actuator_path("rig A/left coil"), dir / "rig_A_left_coil.json");
  try {
    find_actuator("rig A/left coil");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("none stored yet"), std::string::npos) << e.what();
  }
  std::ofstream(actuator_path("rig A/left coil")) << "{}";
  EXPECT_EQ(find_actuator("rig A/left coil"), dir / "rig_A_left_coil.json");
  EXPECT_EQ(find_actuator((dir / "rig_A_left_coil.json").string()), dir / "rig_A_left_coil.json");
  try {
    find_actuator("right coil");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("stored: rig_A_left_coil"), std::string::npos) << e.what();
  }
  ::unsetenv("NIBRIG_ACTUATORS");
}

}  // namespace
}  // namespace nibrig::playback
