// The Experiment view's rehearsal: the experimenter names a space, and a simulated participant
// answers every trial from it through the participant's own screens, so that the whole session and
// its files can be seen before anyone comes in. Checked against the library's session run by the
// same simulated participant: the panel's frames must neither lose nor add a play or an answer,
// also across a stop and a resume.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <thread>

#include "model/study/response_log.hpp"
#include "model/study/simulated_participant.hpp"
#include "model/study/study_results.hpp"
#include "rig/study/study_rehearsal.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/ui/panel/headless_imgui.hpp"
#include "tests/ui/panel/test_space.hpp"
#include "ui/panel/experiment_view.hpp"

namespace nibrig::ui::panel {
namespace {

namespace study = model::study;

// Frames until the view leaves `stage` (or a minute passes).
void frames_while(testing::HeadlessImGui& imgui, ExperimentView& view, ExperimentView::Stage stage,
                  std::size_t at_most_answers = SIZE_MAX) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::minutes(1);
  while (std::chrono::steady_clock::now() < until) {
    const bool in = view.stage() == stage || (stage == ExperimentView::Stage::trial &&
                                               (view.stage() == ExperimentView::Stage::rest ||
                                                view.stage() == ExperimentView::Stage::consent));
    if (!in) return;
    if (view.session() && view.session()->begun() && view.session()->result().answered >= at_most_answers) return;
    imgui.frame([&] { view.draw(); });
    if (stage == ExperimentView::Stage::preparing) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

// The same participant's whole session, run by the library alone (no view): what the panel's
// rehearsal must have written.
std::vector<study::LoggedResponse> reference_session(const std::filesystem::path& folder,
                                                  const std::filesystem::path& stimuli,
                                                  const std::filesystem::path& space) {
  rig::StudyStartRequest request;
  study::StudyDefinition d;
  d.stimuli = study::read_stimulus_list(stimuli);
  d.practice = 1;
  d.break_every = 5;
  request.definition = d;
  request.settings.study = folder;
  request.settings.participant = "S01";
  rig::StudyStart start(std::move(request));
  rig::Rehearsal rehearsal = rig::rehearse_from(start, space, 0.0);
  start.prepare();
  rig::ReadyStudy ready = start.ready();
  const study::StudyResult r = study::run_study(*ready.session, *rehearsal.participant);
  EXPECT_TRUE(r.complete);
  return study::read_study(folder).participants.at(0).responses;
}

// The form of participant S01 in <dir>/study, rehearsed from `space` with <dir>/stimuli.txt.
void rehearsal_form(ExperimentView& view, const std::filesystem::path& dir, const std::filesystem::path& space) {
  view.form().study = (dir / "study").string();
  view.form().stimuli = (dir / "stimuli.txt").string();
  view.form().participant = "S01";
  view.form().rehearse = space.string();
}

TEST(ExperimentRehearsal, ASimulatedParticipantAnswersEveryTrialThroughTheScreensAsTheLibraryRunsIt) {
  const auto dir = nibrig::test::scratch_dir("panel_experiment_rehearsal");
  const auto space = testing::write_descriptor_space(dir);
  std::ofstream(dir / "stimuli.txt") << "cryon/office\nstab/office\nvero2/office\nDM851/office\n";
  const auto expected = reference_session(dir / "reference", dir / "stimuli.txt", space);
  ASSERT_GT(expected.size(), 5u) << "a rest is due within the session";

  testing::HeadlessImGui imgui;
  PanelAudio audio(model::design::ToolSoundOptions{});
  ExperimentView view(audio, [] { return model::design::ToolSoundOptions{}; });
  rehearsal_form(view, dir, space);
  view.form().practice = 1;
  view.form().break_every = 5;
  view.form().pace = 0.0;  // one move a frame
  view.start();
  ASSERT_EQ(view.error(), "");
  frames_while(imgui, view, ExperimentView::Stage::preparing);
  ASSERT_TRUE(view.fullscreen()) << view.error();  // consent, agreed to in the same frame
  EXPECT_TRUE(view.rehearsing());
  EXPECT_FALSE(audio.audition_lent()) << "a rehearsal plays nothing on the actuator";

  // Stopped after three answers (Esc, as an experimenter would), then resumed from the form.
  frames_while(imgui, view, ExperimentView::Stage::trial, 3);
  ASSERT_EQ(view.session()->result().answered, 3u);
  view.stop();
  EXPECT_FALSE(view.rehearsing());
  EXPECT_TRUE(view.form().resume);
  view.start();
  ASSERT_EQ(view.error(), "");
  frames_while(imgui, view, ExperimentView::Stage::preparing);
  frames_while(imgui, view, ExperimentView::Stage::trial);
  ASSERT_EQ(view.stage(), ExperimentView::Stage::done) << view.error();

  const auto logged = study::read_study(dir / "study").participants.at(0);
  EXPECT_EQ(logged.record.respondent.rfind("simulated from " + space.string(), 0), 0u) << logged.record.respondent;
  ASSERT_EQ(logged.responses.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    SCOPED_TRACE("trial " + std::to_string(i + 1));
    EXPECT_EQ(logged.responses[i].planned.reference, expected[i].planned.reference);
    EXPECT_EQ(logged.responses[i].planned.left, expected[i].planned.left);
    EXPECT_EQ(logged.responses[i].planned.right, expected[i].planned.right);
    EXPECT_EQ(logged.responses[i].plays, expected[i].plays);
    EXPECT_EQ(logged.responses[i].chosen, expected[i].chosen);
    // The modelled response time is recorded, not the frames' (a frame is milliseconds); the log
    // keeps it to the millisecond.
    EXPECT_NEAR(logged.responses[i].response_s, expected[i].response_s, 1e-3);
  }
}

TEST(ExperimentRehearsal, ASpaceThatCannotPlaceAStimulusIsRefusedBeforeTheStudyIsMade) {
  const auto dir = nibrig::test::scratch_dir("panel_experiment_rehearsal_refused");
  const auto space = testing::write_small_space(dir);  // no map, and no office crayon's neighbours
  std::ofstream(dir / "stimuli.txt") << "cryon/office\nstab/office\nvero2/office\nDM851/office\n";
  testing::HeadlessImGui imgui;
  PanelAudio audio(model::design::ToolSoundOptions{});
  ExperimentView view(audio, [] { return model::design::ToolSoundOptions{}; });
  rehearsal_form(view, dir, space);
  view.start();
  frames_while(imgui, view, ExperimentView::Stage::preparing);
  EXPECT_EQ(view.stage(), ExperimentView::Stage::setup);
  EXPECT_NE(view.error().find(space.string()), std::string::npos) << view.error();
  EXPECT_NE(view.error().find("stab/office"), std::string::npos) << view.error();
}

}  // namespace
}  // namespace nibrig::ui::panel
