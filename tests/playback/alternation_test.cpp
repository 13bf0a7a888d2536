// The A/B or triplet presentation heard in turn, on an audition with no device (the timing and the
// order are what is tested; what a switch sounds like is LiveAudition's test).
#include "playback/alternation.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "tests/rt/test_voices.hpp"

namespace nibrig::playback {
namespace {

struct AlternationSwitch {
  double t_s;
  std::size_t slot;
};

// An audition with `slots` voices loaded and no device.
std::unique_ptr<LiveAudition> alternation_audition(std::size_t slots) {
  rt::EngineSettings settings;
  settings.slots = slots;
  auto audition = std::make_unique<LiveAudition>(settings);
  static const auto spectrum = rt::testing::catalog_spectrum("cryon", "note");
  for (std::size_t i = 0; i < slots; ++i)
    audition->load(i, {"cryon " + std::to_string(i), "small stylus", rt::testing::small_stylus(),
                       spectrum},
                   i);
  audition->attach(std::make_unique<rt::SweepStroke>());
  return audition;
}

TEST(Alternation, SwitchesRoundTheSlotsOnTimeAndStopsAtTheEnd) {
  auto audition = alternation_audition(3);
  std::vector<AlternationSwitch> switches;
  AlternationEvents events;
  events.switched = [&](double t, std::size_t slot) { switches.push_back({t, slot}); };
  play_in_turn(*audition, {0.75, 0.2}, events);
  // Due at 0.2, 0.4 and 0.6 s; a loaded machine may poll late (and then switch late, never early or
  // twice at once), so at least the first is certain and no more than three fit in 0.75 s.
  ASSERT_GE(switches.size(), 1u);
  ASSERT_LE(switches.size(), 3u);
  for (std::size_t k = 0; k < switches.size(); ++k) {
    EXPECT_EQ(switches[k].slot, (k + 1) % 3) << "switch " << k;
    EXPECT_GE(switches[k].t_s, 0.2 * static_cast<double>(k + 1)) << "switch " << k << " came early";
    EXPECT_LT(switches[k].t_s, 0.75) << "switch " << k << " came after the end";
  }
  EXPECT_EQ(audition->selected(), switches.back().slot);
}

TEST(Alternation, OneSlotPlaysWithoutSwitching) {
  auto audition = alternation_audition(1);
  bool switched = false;
  AlternationEvents events;
  events.switched = [&](double, std::size_t) { switched = true; };
  play_in_turn(*audition, {0.3, 0.1}, events);
  EXPECT_FALSE(switched);
  EXPECT_EQ(audition->selected(), 0u);
}

TEST(Alternation, RefusesATimeThatIsNotPositive) {
  auto audition = alternation_audition(2);
  EXPECT_THROW(play_in_turn(*audition, {0.0, 0.1}), std::invalid_argument);
  EXPECT_THROW(play_in_turn(*audition, {1.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(play_in_turn(*audition, {1.0, -2.0}), std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::playback
