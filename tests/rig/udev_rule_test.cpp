// The udev rule installed with nibrig (rig/70-nibrig-rig.rules) opens the device the firmware
// announces: its vendor and product IDs are the protocol header's, as the rule's text gives them.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "rig/firmware/rig_protocol.h"

namespace nibrig::rig {
namespace {

TEST(UdevRule, OpensTheDeviceTheFirmwareAnnounces) {
  std::ifstream in(NIBRIG_SOURCE_DIR "/rig/70-nibrig-rig.rules");
  ASSERT_TRUE(in) << "rig/70-nibrig-rig.rules";
  std::stringstream text;
  text << in.rdbuf();
  const std::string rules = text.str();
  const std::regex device(
      R"re(ATTR\{idVendor\}=="([0-9a-f]{4})", ATTR\{idProduct\}=="([0-9a-f]{4})".*MODE="0660")re");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(rules, m, device)) << rules;
  EXPECT_EQ(std::stoul(m[1].str(), nullptr, 16), RIG_USB_VENDOR_ID);
  EXPECT_EQ(std::stoul(m[2].str(), nullptr, 16), RIG_USB_PRODUCT_ID);
}

}  // namespace
}  // namespace nibrig::rig
