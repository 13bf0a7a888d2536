// The experiment runner's rig mode: the operator is told each trial's tools and what to mount
// when it changes, and every stimulus asked for runs the study's sweep on the rig (here the
// simulated rig, simulating the stimulus). A rig that ends a sweep early (unplugged) stops the
// session with every earlier answer kept.
#include "rig/study/turntable_presenter.hpp"

#include <gtest/gtest.h>

#include "model/study/study_results.hpp"
#include "rig/simulated_rig.hpp"
#include "tests/model/study/study_test_support.hpp"
#include "tests/rig/bundled_sound.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::rig {
namespace {

namespace study = model::study;

class ScriptedTurntableParticipant final : public study::Respondent {
 public:
  explicit ScriptedTurntableParticipant(std::vector<std::string> scripts) : scripts_(std::move(scripts)) {}
  bool agree(const study::StudyTexts&) override { return true; }
  study::Answer answer(const study::TrialPrompt& prompt,
                       const std::function<void(study::Role)>& play) override {
    for (char c : scripts_.at(prompt.number - 1)) play(static_cast<study::Role>(c));
    return {model::space::Choice::right, 4.0};
  }
  void rest(std::size_t, std::size_t) override {}

 private:
  std::vector<std::string> scripts_;
};

study::StudyDefinition turntable_study() {
  study::StudyDefinition d;
  d.stimuli = {{"cryon/note", "cryon", "note"}, {"stab/office", "stab", "office"},
               {"vero2/glass", "vero2", "glass"}};
  d.mode = study::StudyMode::rig;
  d.plan = study::PlanKind::file;
  d.practice = 0;
  d.listed_trials = {{0, 1, 2, 1}, {1, 2, 0, 1}};
  return d;
}

std::unique_ptr<Rig> simulated_rig_of(const study::Stimulus& s) {
  SimulatedRigSettings settings;
  settings.speedup = 0;  // as fast as it computes
  return std::make_unique<SimulatedRig>(settings, testing::bundled_sound(s.tool, s.surface), s.tool,
                                        s.surface);
}

study::StudySettings turntable_session(const std::filesystem::path& folder) {
  study::StudySettings s;
  s.study = folder;
  s.participant = "P01";
  return s;
}

TEST(StudyTurntable, TellsTheOperatorWhatToMountAndRunsASweepForEveryStimulusAskedFor) {
  const auto folder = study::test::make_study(nibrig::test::scratch_dir("study_turntable"), turntable_study());
  std::vector<std::string> told;
  const auto tell = [&](const std::string& m) { told.push_back(m); };
  TurntablePresenter presenter(turntable_study().stimuli, simulated_rig_of, tell, tell);
  // Trial 1 asks for the reference twice in a row (mounted once), trial 2 alternates.
  ScriptedTurntableParticipant participant({"RRAB", "RARB"});
  ASSERT_TRUE(study::run_study(turntable_session(folder), presenter, participant).complete);
  EXPECT_EQ(presenter.runs(), 8u);
  EXPECT_EQ(presenter.mounts(), 3u + 4u);
  ASSERT_GE(told.size(), 3u);
  EXPECT_EQ(told[0], "trial with reference cryon/note, A stab/office, B vero2/glass: have them at hand");
  EXPECT_EQ(told[1], "mount cryon on note (the reference)");
  EXPECT_EQ(told[2], "mount stab on office (A)");
  const auto logged = study::read_study(folder).participants.at(0).responses;
  ASSERT_EQ(logged.size(), 2u);
  EXPECT_EQ(logged[0].plays, "RRAB");
}

// A rig unplugged in the middle of its sweep (a fault the test makes on purpose).
class UnpluggedRig final : public Rig {
 public:
  UnpluggedRig() { description_.kind = "usb", description_.name = "USB rig NIB-0001"; }
  const RigDescription& description() const override { return description_; }
  void start(const SpeedProfile&) override {}
  bool read(RigData&, std::chrono::milliseconds) override { return false; }
  void stop() override {}
  RigHealth health() const override {
    RigHealth h;
    h.connected = false;
    h.ended_because = "the rig controller was unplugged (no device)";
    return h;
  }

 private:
  RigDescription description_;
};

TEST(StudyTurntable, ARigUnpluggedMidSweepStopsTheSessionAndKeepsEveryEarlierAnswer) {
  const auto folder =
      study::test::make_study(nibrig::test::scratch_dir("study_turntable_unplugged"), turntable_study());
  std::size_t opened = 0;
  TurntablePresenter presenter(
      turntable_study().stimuli,
      [&](const study::Stimulus& s) -> std::unique_ptr<Rig> {
        return ++opened <= 3 ? simulated_rig_of(s) : std::make_unique<UnpluggedRig>();
      },
      [](const std::string&) {});
  ScriptedTurntableParticipant participant({"RAB", "RAB"});
  try {
    study::run_study(turntable_session(folder), presenter, participant);
    ADD_FAILURE() << "the unplugged rig went unnoticed";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("unplugged"), std::string::npos) << e.what();
  }
  EXPECT_EQ(study::read_study(folder).participants.at(0).responses.size(), 1u);
}

}  // namespace
}  // namespace nibrig::rig
