// A rig opened with its profile, as every face opens one: the named profile for a simulated rig
// (checked before anything opens), a replayed rig's own recorded profile cut to the seconds asked,
// and the refusals; and which tool a comparison simulates.
#include "rig/rig_request.hpp"

#include <gtest/gtest.h>

#include "model/design/tool_sound.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::rig {
namespace {

const std::filesystem::path kPaperVero2 = "piovarci2018/vibration/prints/arm_plain_vero_2_office.csv.gz";

TEST(RigRequest, ASimulatedRigRunsTheProfileAskedOrTheFacesDefault) {
  model::design::ToolSounds sounds({});
  RigRequest request;
  request.tool = "vero2", request.surface = "office", request.speedup = 0.0;
  const OpenedRig named = open_rig_with_profile(request, sounds, "sweep", "steps", 4.5);
  EXPECT_EQ(named.rig->description().kind, "simulated");
  EXPECT_DOUBLE_EQ(named.profile.duration_s(), 4.5);  // cut to the seconds asked
  const OpenedRig fallback = open_rig_with_profile(request, sounds, "", "steps", std::nullopt);
  EXPECT_DOUBLE_EQ(fallback.profile.duration_s(), 42.0);  // the paper's protocol, 42 s (rig_request.hpp)
  EXPECT_THROW(open_rig_with_profile(request, sounds, "zigzag", "steps", std::nullopt), std::invalid_argument);
}

TEST(RigRequest, AReplayRunsWhatItRecordedCutToTheSecondsAndRefusesAnotherProfile) {
  model::design::ToolSounds sounds({});
  RigRequest request;
  request.kind = RigKind::replay;
  request.replay = nibrig::test::shared_data() / kPaperVero2;
  request.speedup = 0.0;
  const OpenedRig whole = open_rig_with_profile(request, sounds, "", "sweep", std::nullopt);
  ASSERT_NE(whole.rig->own_profile(), nullptr);
  EXPECT_DOUBLE_EQ(whole.profile.duration_s(), whole.rig->own_profile()->duration_s());
  const OpenedRig cut = open_rig_with_profile(request, sounds, "", "sweep", 10.0);
  EXPECT_DOUBLE_EQ(cut.profile.duration_s(), 10.0);
  try {
    open_rig_with_profile(request, sounds, "steps", "sweep", std::nullopt);
    FAIL() << "a replay took another profile";
  } catch (const RigRequestRefused& e) {
    EXPECT_EQ(e.field(), RigRequestRefused::Field::profile) << e.what();
  }
  EXPECT_THROW(open_rig_with_profile(request, sounds, "", "sweep", -1.0), RigRequestRefused);
}

TEST(RigRequest, AComparisonSimulatesWhatIsAskedElseWhatIsMounted) {
  RigDescription mounted;
  mounted.tool = "vero2", mounted.surface = "office";
  const auto asked = simulated_choice(mounted, "DM85:1,tip=2mm", "");
  EXPECT_EQ(asked.tool, "DM85:1,tip=2mm");
  EXPECT_EQ(asked.surface, "office");
  const auto own = simulated_choice(mounted, "", "glass");
  EXPECT_EQ(own.tool, "vero2");
  EXPECT_EQ(own.surface, "glass");
  EXPECT_THROW(simulated_choice(RigDescription{}, "", "office"), std::invalid_argument);  // a USB rig knows nothing
}

// Issue 46: rig.capture(seconds=1e-320) made a 0-frame session and rig.simulated(load=1e308) one
// its own reader refused; the library holds every face to the command line's ranges, naming what.
TEST(RigRequestBounds, LoadAndSecondsAreHeldToTheOptionsRanges) {
  try {
    check_load(1e308, "load");
    FAIL() << "a load of 1e308 N passed";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("load: 1e+308 N"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(check_load(2.2, "load"));
  try {
    profile_named("steps", 1e-320);
    FAIL() << "a capture of 1e-320 s passed";
  } catch (const RigRequestRefused& e) {
    EXPECT_EQ(e.field(), RigRequestRefused::Field::seconds) << e.what();
  }
}

}  // namespace
}  // namespace nibrig::rig
