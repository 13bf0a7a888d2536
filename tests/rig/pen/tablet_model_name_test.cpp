// Naming a tablet's model from libwacom's match lines for its USB id and the kernel's device name:
// the rule alone, on match lines written here (pen_tablets_of_every_maker_test.cpp runs it on the
// installed database through libinput).
#include "rig/pen/tablet_model_name.hpp"

#include <gtest/gtest.h>

#include <set>

namespace nibrig::rig::pen {
namespace {

const std::vector<LibwacomMatch> kSharedId = {
    {"Huion H640P", "HUION Huion Tablet_H640P Pen", 152.4, 101.6},
    {"Huion H640P", "HUION Huion Tablet_H640P Pad", 152.4, 101.6},
    {"Huion H950P", "", 228.6, 127.0},
    {"GAOMON S620", "GAOMON Gaomon Tablet Pen", 152.4, 101.6},
    {"HUION H1060P Tablet", "HUION Huion Tablet Pen", 254.0, 152.4},
};

TEST(TabletModelName, TheDevicesOwnNameTellsTheModelApartOnASharedId) {
  const auto named = name_tablet_model(kSharedId, "HUION Huion Tablet_H640P Pen", 0x256c, 0x006d);
  EXPECT_EQ(named.model, "Huion H640P");
  EXPECT_TRUE(named.told_apart);
  EXPECT_EQ(named.width_mm, 152.4);
}

// The id-only line (H950P) is what libwacom's lookup by id returns: never claimed for a device
// whose name no line names, as a dozen models share the id.
TEST(TabletModelName, ASharedIdWithAnUnmatchedNameClaimsNoModelAndSaysWhy) {
  const auto named = name_tablet_model(kSharedId, "HID 256c:006d Pen", 0x256c, 0x006d);
  EXPECT_EQ(named.model, "a GAOMON or Huion tablet (model not told apart by its USB id 256c:006d)");
  EXPECT_FALSE(named.told_apart);
  EXPECT_EQ(named.width_mm, 0.0);
}

TEST(TabletModelName, AnIdListedForOneModelNamesItWhateverTheDevicesName) {
  const std::vector<LibwacomMatch> one = {{"Wacom Intuos S", "", 152.4, 101.6}};
  const auto named = name_tablet_model(one, "Wacom Intuos S Pen", 0x056a, 0x0374);
  EXPECT_EQ(named.model, "Wacom Intuos S");
  EXPECT_TRUE(named.told_apart);
}

// One model listed only by device names that are not this device's: the id does not tell it.
TEST(TabletModelName, AModelListedOnlyByOtherNamesIsNotClaimed) {
  const std::vector<LibwacomMatch> one = {{"Huion Kamvas 13", "HUION Huion Tablet_GS1331 Pen", 304.8, 177.8}};
  const auto named = name_tablet_model(one, "HUION Huion Tablet_GS1561 Pen", 0x256c, 0x006d);
  EXPECT_FALSE(named.told_apart);
  EXPECT_EQ(named.model, "a Huion tablet (model not told apart by its USB id 256c:006d)");
}

TEST(TabletModelName, AnIdLibwacomDoesNotListGivesNoModel) {
  const auto named = name_tablet_model({}, "Some Tablet Pen", 0x1234, 0x5678);
  EXPECT_EQ(named.model, "");
  EXPECT_FALSE(named.told_apart);
}

// The installed database (libwacom 2.6's data files) lists 256c:006d for six models of two makers.
TEST(TabletModelName, TheInstalledDatabaseListsHuionsSharedIdForSeveralModels) {
  const auto matches = libwacom_usb_matches(0x256c, 0x006d);
  std::set<std::string> models;
  for (const auto& m : matches) models.insert(m.model);
  EXPECT_GE(models.size(), 5u);
  EXPECT_EQ(models.count("Huion H640P"), 1u);
  EXPECT_EQ(models.count("Huion H950P"), 1u);
}

}  // namespace
}  // namespace nibrig::rig::pen
