// What the panel remembers between runs comes back as it was kept; a missing file gives the
// defaults and a damaged one an error naming the file and what is wrong (the panel shows it).
#include "ui/panel/panel_settings.hpp"

#include <gtest/gtest.h>

#include <fstream>

namespace nibrig::ui::panel {
namespace {

std::filesystem::path scratch() {
  const auto dir = std::filesystem::path(NIBRIG_TEST_BINARY_DIR) / "scratch" / "panel_settings";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

TEST(PanelSettings, WhatWasKeptComesBack) {
  const auto file = scratch() / "nested" / "panel.json";
  PanelSettings s;
  s.view = View::rig;
  s.device = DeviceRequest{"jack", "system", 2, 128};
  s.space = "/somewhere/space.json";
  s.stroke.kind = 0;
  s.stroke.speed_mm_s = 42.0f;
  s.rig.kind = 1;
  s.rig.replay = "/sessions/one";
  s.rig.speedup = 4.0f;
  s.rig.play_on_actuator = true;
  s.printer = "prusa-sl1s";
  write_panel_settings(file, s);
  const PanelSettings back = read_panel_settings(file);
  EXPECT_EQ(back.view, View::rig);
  ASSERT_TRUE(back.device.has_value());
  EXPECT_EQ(back.device->device, "system");
  EXPECT_EQ(back.device->output_channel, 2u);
  EXPECT_EQ(back.device->period_frames, 128u);
  EXPECT_EQ(back.space, "/somewhere/space.json");
  EXPECT_EQ(back.stroke.kind, 0);
  EXPECT_EQ(back.stroke.speed_mm_s, 42.0f);
  EXPECT_EQ(back.rig.kind, 1);
  EXPECT_EQ(back.rig.replay, "/sessions/one");
  EXPECT_EQ(back.rig.speedup, 4.0f);
  EXPECT_TRUE(back.rig.play_on_actuator);
  EXPECT_EQ(back.printer, "prusa-sl1s");
}

TEST(PanelSettings, AMissingFileGivesTheDefaultsAndADamagedOneSaysWhere) {
  const auto dir = scratch();
  const PanelSettings none = read_panel_settings(dir / "absent.json");
  EXPECT_EQ(none.view, View::space);
  EXPECT_FALSE(none.device.has_value());
  const auto bad = dir / "bad.json";
  std::ofstream(bad) << R"({"view": "spreadsheet"})";
  try {
    read_panel_settings(bad);
    FAIL() << "a view that does not exist was read";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("bad.json"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("spreadsheet"), std::string::npos) << e.what();
  }
  std::ofstream(dir / "cut.json") << R"({"view": "rig", "dev)";
  EXPECT_THROW(read_panel_settings(dir / "cut.json"), std::runtime_error);
}

}  // namespace
}  // namespace nibrig::ui::panel
