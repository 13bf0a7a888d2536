// The panel's Experiment view driven without a window: the experimenter's form makes the study,
// the stimuli's sounds are made in the background, then the participant's screen takes over (the
// panel shows nothing else), answers go to disk as they are given, an answer before all three
// stimuli were felt does not count, and Stop then Resume continues with the next trial.
#include "ui/panel/experiment_view.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <thread>

#include "model/study/study_results.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/ui/panel/headless_imgui.hpp"

namespace nibrig::ui::panel {
namespace {

namespace study = model::study;

void wait_for_sounds(testing::HeadlessImGui& imgui, ExperimentView& view) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::minutes(5);
  while (view.stage() == ExperimentView::Stage::preparing && std::chrono::steady_clock::now() < until) {
    imgui.frame([&] { view.draw(); });
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

TEST(ExperimentView, RunsAParticipantFromConsentToDiskAndResumesAfterAStop) {
  const auto dir = nibrig::test::scratch_dir("panel_experiment");
  std::ofstream(dir / "stimuli.txt") << "cryon/office\nstab/office\nvero2/office\nDM851/office\n";
  testing::HeadlessImGui imgui;
  PanelAudio audio(model::design::ToolSoundOptions{});
  ExperimentView view(audio, [] { return model::design::ToolSoundOptions{}; });
  view.form().study = (dir / "study").string();
  view.form().stimuli = (dir / "stimuli.txt").string();
  view.form().participant = "P01";
  view.form().practice = 1;
  imgui.frame([&] { view.draw(); });
  EXPECT_FALSE(view.fullscreen());
  view.start();
  ASSERT_EQ(view.error(), "");
  wait_for_sounds(imgui, view);
  ASSERT_EQ(view.stage(), ExperimentView::Stage::consent) << view.error();
  EXPECT_TRUE(view.fullscreen()) << "the participant sees nothing but the study";
  EXPECT_TRUE(audio.audition_lent());
  imgui.frame([&] { view.draw(); });
  view.agree(true);
  ASSERT_EQ(view.stage(), ExperimentView::Stage::trial);

  view.play(study::Role::reference);
  view.play(study::Role::left);
  view.answer(model::space::Choice::left);  // B not felt yet: not counted
  EXPECT_EQ(view.session()->result().answered, 0u);
  view.play(study::Role::right);
  imgui.frame([&] { view.draw(); });
  view.answer(model::space::Choice::right);
  view.play(study::Role::right);
  view.play(study::Role::left);
  view.play(study::Role::reference);
  view.answer(model::space::Choice::left);
  view.play(study::Role::reference);  // trial 3 in progress when stopped: not kept
  view.stop();
  EXPECT_FALSE(view.fullscreen());
  EXPECT_FALSE(audio.audition_lent());

  auto logged = study::read_study(dir / "study").participants.at(0).responses;
  ASSERT_EQ(logged.size(), 2u);
  EXPECT_TRUE(logged[0].practice);
  EXPECT_EQ(logged[0].plays, "RAB");
  EXPECT_EQ(logged[0].chosen, model::space::Choice::right);
  EXPECT_EQ(logged[1].plays, "BAR");

  // Resume: the form keeps the study and the ID; the next trial is trial 3.
  EXPECT_TRUE(view.form().resume);
  view.form().stimuli.clear();
  view.start();
  ASSERT_EQ(view.error(), "");
  wait_for_sounds(imgui, view);
  view.agree(true);
  ASSERT_EQ(view.stage(), ExperimentView::Stage::trial);
  EXPECT_EQ(view.session()->current()->number, 3u);
  for (char c : std::string("RAB")) view.play(static_cast<study::Role>(c));
  view.answer(model::space::Choice::left);
  view.stop();
  logged = study::read_study(dir / "study").participants.at(0).responses;
  EXPECT_EQ(logged.size(), 3u);

  // An unknown tool is refused in the form, naming it, before a study is made.
  std::ofstream(dir / "unknown.txt") << "cryon/office\nquill/office\nstab/office\n";
  view.form().study = (dir / "other").string();
  view.form().stimuli = (dir / "unknown.txt").string();
  view.form().resume = false;
  view.start();
  EXPECT_NE(view.error().find("quill/office"), std::string::npos) << view.error();
  EXPECT_FALSE(std::filesystem::exists(dir / "other"));
  // A new participant with an ID already taken is refused in the form, before anything starts.
  view.form().study = (dir / "study").string();
  view.form().resume = false;
  view.form().stimuli = (dir / "stimuli.txt").string();
  view.start();
  EXPECT_NE(view.error().find("--resume"), std::string::npos) << view.error();
  EXPECT_EQ(view.stage(), ExperimentView::Stage::setup);
}

// Rig mode with the simulated rig (as fast as it computes): asking for a stimulus runs the sweep on
// a worker while the window asks the operator to mount it; the UI thread keeps drawing.
TEST(ExperimentView, InRigModeTheOperatorMountsEachToolAndTheTurntableRunsOffTheUiThread) {
  const auto dir = nibrig::test::scratch_dir("panel_experiment_rig");
  std::ofstream(dir / "stimuli.txt") << "cryon/office\nstab/office\nvero2/office\n";
  testing::HeadlessImGui imgui;
  PanelAudio audio(model::design::ToolSoundOptions{});
  ExperimentView view(audio, [] { return model::design::ToolSoundOptions{}; }, [] {
    rig::RigRequest r;
    r.kind = rig::RigKind::simulated;
    r.speedup = 0;
    return r;
  });
  view.form() = {(dir / "study").string(), (dir / "stimuli.txt").string(), "R01", 2, false, 0, 100, false};
  view.start();
  ASSERT_EQ(view.error(), "");
  wait_for_sounds(imgui, view);
  ASSERT_EQ(view.stage(), ExperimentView::Stage::consent) << view.error();
  EXPECT_FALSE(audio.audition_lent()) << "the actuator is not used in rig mode";
  view.agree(true);
  EXPECT_NE(view.operator_notice().find("have them at hand"), std::string::npos);
  std::vector<std::string> asked;
  for (char c : std::string("RAB")) {
    ASSERT_EQ(view.stage(), ExperimentView::Stage::trial) << view.error();
    view.play(static_cast<study::Role>(c));
    EXPECT_EQ(view.stage(), ExperimentView::Stage::presenting);
    const auto until = std::chrono::steady_clock::now() + std::chrono::minutes(2);
    while (view.stage() == ExperimentView::Stage::presenting && std::chrono::steady_clock::now() < until) {
      imgui.frame([&] { view.draw(); });  // the UI keeps drawing meanwhile
      if (const std::string r = view.operator_request(); !r.empty()) {
        asked.push_back(r);
        view.operator_done();
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  }
  ASSERT_EQ(asked.size(), 3u);
  EXPECT_EQ(asked[0].rfind("mount ", 0), 0u) << asked[0];
  view.answer(model::space::Choice::left);
  // Stopped while the operator is asked to mount: the worker stops waiting, nothing more is kept.
  view.play(study::Role::reference);
  view.stop();
  EXPECT_EQ(view.stage(), ExperimentView::Stage::setup);
  const auto logged = study::read_study(dir / "study").participants.at(0).responses;
  ASSERT_EQ(logged.size(), 1u);
  EXPECT_EQ(logged[0].plays, "RAB");
}

}  // namespace
}  // namespace nibrig::ui::panel
