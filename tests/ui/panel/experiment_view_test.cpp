// The panel's Experiment view driven without a window: the experimenter's form shows the plan's
// size and duration as the library works them out and makes the study, the stimuli's sounds are
// made in the background under a bar that names each, then the participant's screen takes over (the
// panel shows nothing else), answers go to disk as they are given, an answer before all three
// stimuli were felt does not count, and Stop then Resume continues with the next trial.
#include "ui/panel/experiment_view.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <random>
#include <thread>

#include "model/space/simulated_observer.hpp"
#include "model/study/simulated_participant.hpp"
#include "model/study/study_results.hpp"
#include "model/study/trial_sequence.hpp"
#include "rt/stroke_source.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/ui/panel/headless_imgui.hpp"

namespace nibrig::ui::panel {
namespace {

namespace study = model::study;

// Frames until the sounds are made; what the preparing bar said at each.
std::vector<std::string> wait_for_sounds(testing::HeadlessImGui& imgui, ExperimentView& view) {
  std::vector<std::string> labels;
  const auto until = std::chrono::steady_clock::now() + std::chrono::minutes(5);
  while (view.stage() == ExperimentView::Stage::preparing && std::chrono::steady_clock::now() < until) {
    labels.push_back(view.preparing_label());
    imgui.frame([&] { view.draw(); });
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return labels;
}

// Frames until the form's plan is worked out (on its background job).
const PlanPreview* wait_for_plan(testing::HeadlessImGui& imgui, ExperimentView& view) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::minutes(2);
  while (!view.plan() && std::chrono::steady_clock::now() < until) {
    imgui.frame([&] { view.draw(); });
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return view.plan();
}

// The study a list makes, built here from the library alone (not the view's own helper).
study::StudyDefinition study_of(const std::filesystem::path& list, bool adaptive, std::size_t practice,
                                std::size_t trials) {
  study::StudyDefinition d;
  d.stimuli = study::read_stimulus_list(list);
  d.plan = adaptive ? study::PlanKind::adaptive : study::PlanKind::two_stage;
  d.practice = practice;
  d.trials = trials;
  return d;
}

// The runner's estimate as `nibrig experiment run` makes it: five simulated participants, seeds
// from 1, answering from a random space drawn with seed 1.
study::TrialEstimate estimate_of(const study::StudyDefinition& d) {
  std::mt19937_64 generator(1);
  return study::estimate_trials(d, model::space::random_space(d.dims, d.stimuli.size(), generator), 5, 1);
}

TEST(ExperimentView, TheFormShowsThePlansSizeAndDurationAsTheLibraryWorksThemOutAndFollowsTheForm) {
  const auto dir = nibrig::test::scratch_dir("panel_experiment_plan");
  std::ofstream(dir / "stimuli.txt") << "cryon/office\nstab/office\nvero2/office\nDM851/office\n";
  testing::HeadlessImGui imgui;
  PanelAudio audio(model::design::ToolSoundOptions{});
  ExperimentView view(audio, [] { return model::design::ToolSoundOptions{}; });

  // No list yet: one line says why there is no plan.
  view.form().study = (dir / "study").string();
  const PlanPreview* none = wait_for_plan(imgui, view);
  ASSERT_NE(none, nullptr);
  EXPECT_NE(none->problem.find("no stimulus list"), std::string::npos) << none->problem;
  ASSERT_EQ(plan_lines(*none).size(), 1u);

  // A list of four: the plan's numbers are the library's, exactly (the same calls, same seeds).
  view.form().stimuli = (dir / "stimuli.txt").string();
  view.form().practice = 1;
  EXPECT_EQ(view.plan(), nullptr) << "the plan shown was not of the form as it is now";
  const PlanPreview* p = wait_for_plan(imgui, view);
  ASSERT_NE(p, nullptr);
  ASSERT_EQ(p->problem, "");
  auto d = study_of(dir / "stimuli.txt", false, 1, 0);
  const std::size_t at_most = study::TrialSequence(d, 1).expected_at_most();
  const study::TrialEstimate e = estimate_of(d);
  EXPECT_EQ(p->stimuli, 4u);
  EXPECT_EQ(p->practice, 1u);
  EXPECT_EQ(p->at_most, at_most);
  EXPECT_EQ(p->estimate.least, e.least);
  EXPECT_EQ(p->estimate.most, e.most);
  EXPECT_EQ(p->estimate.mean, e.mean);  // the same runs, summed in the same order
  EXPECT_GE(p->estimate.least, 1u + 1u);  // the practice trial and at least one main trial
  // No one has answered yet: the least a trial takes, its three stimuli felt once, 3 s each.
  EXPECT_NEAR(p->seconds_per_trial, 3 * rt::SweepStroke::kPaperPeriod, 1e-12);
  EXPECT_NEAR(p->expected_s(), e.mean * 3 * rt::SweepStroke::kPaperPeriod, 1e-9);  // a product of the two
  const auto lines = plan_lines(*p);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_NE(lines[0].find("at most " + std::to_string(at_most)), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find("1 practice"), std::string::npos) << lines[0];
  EXPECT_NE(lines[1].find("expected duration"), std::string::npos) << lines[1];

  // The experimenter asks for 12 main trials and 3 practice: the plan follows.
  view.form().trials = 12;
  view.form().practice = 3;
  p = wait_for_plan(imgui, view);
  ASSERT_NE(p, nullptr);
  ASSERT_EQ(p->problem, "");
  d = study_of(dir / "stimuli.txt", false, 3, 12);
  EXPECT_EQ(p->practice, 3u);
  EXPECT_EQ(p->at_most, study::TrialSequence(d, 1).expected_at_most());
  EXPECT_NE(p->at_most, at_most);
  EXPECT_EQ(p->estimate.mean, estimate_of(d).mean);
  // The adaptive plan instead.
  view.form().adaptive = true;
  p = wait_for_plan(imgui, view);
  ASSERT_NE(p, nullptr);
  ASSERT_EQ(p->problem, "");
  d = study_of(dir / "stimuli.txt", true, 3, 12);
  EXPECT_EQ(p->at_most, study::TrialSequence(d, 1).expected_at_most());
  EXPECT_EQ(p->estimate.mean, estimate_of(d).mean);

  // A list that is not there: the one line names it.
  view.form().stimuli = (dir / "missing.txt").string();
  p = wait_for_plan(imgui, view);
  ASSERT_NE(p, nullptr);
  EXPECT_NE(p->problem.find("missing.txt"), std::string::npos) << p->problem;
}

TEST(ExperimentView, CancelWhileTheSoundsAreMadeReturnsToTheForm) {
  const auto dir = nibrig::test::scratch_dir("panel_experiment_cancel");
  std::ofstream(dir / "stimuli.txt") << "cryon/office\nstab/office\nvero2/office\nDM851/office\n";
  testing::HeadlessImGui imgui;
  PanelAudio audio(model::design::ToolSoundOptions{});
  ExperimentView view(audio, [] { return model::design::ToolSoundOptions{}; });
  view.form().study = (dir / "study").string();
  view.form().stimuli = (dir / "stimuli.txt").string();
  view.form().participant = "P01";
  view.start();
  ASSERT_EQ(view.error(), "");
  ASSERT_EQ(view.stage(), ExperimentView::Stage::preparing);
  EXPECT_EQ(view.preparing_label().rfind("making the stimuli's sounds: ", 0), 0u) << view.preparing_label();
  imgui.frame([&] { view.draw(); });
  view.stop();  // what the bar's Cancel does
  EXPECT_EQ(view.stage(), ExperimentView::Stage::setup);
  EXPECT_FALSE(view.fullscreen());
  EXPECT_EQ(view.preparing_label(), "");
  // Start again: the study made before is joined, the sounds made, the consent shown.
  view.form().resume = false;
  view.start();
  ASSERT_EQ(view.error(), "");
  wait_for_sounds(imgui, view);
  EXPECT_EQ(view.stage(), ExperimentView::Stage::consent) << view.error();
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
  const std::vector<std::string> labels = wait_for_sounds(imgui, view);
  ASSERT_EQ(view.stage(), ExperimentView::Stage::consent) << view.error();
  EXPECT_TRUE(view.fullscreen()) << "the participant sees nothing but the study";
  // The bar was labelled from its first frame, and named the sounds as they were made.
  ASSERT_FALSE(labels.empty());
  for (const auto& label : labels) EXPECT_EQ(label.rfind("making the stimuli's sounds: ", 0), 0u) << label;
  const auto named = [&](const std::string& text) {
    return std::any_of(labels.begin(), labels.end(),
                       [&](const std::string& l) { return l.find(text) != std::string::npos; });
  };
  EXPECT_TRUE(named("1 of 4 (cryon/office)") || named("2 of 4 (stab/office)") || named("3 of 4 (vero2/office)") ||
              named("4 of 4 (DM851/office)"))
      << "no label named a sound: " << labels.front() << " ... " << labels.back();
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
  // The form's own checkbox is named, not the command line's option.
  EXPECT_NE(view.error().find("continue with \"resume this participant\""), std::string::npos) << view.error();
  EXPECT_EQ(view.error().find("--resume"), std::string::npos) << view.error();
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
  ExperimentView::Form form;
  form.study = (dir / "study").string();
  form.stimuli = (dir / "stimuli.txt").string();
  form.participant = "R01";
  form.mode = 2;
  form.practice = 0;
  view.form() = form;
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
