// View 6, the experiment: one participant's session of a triplet study in the window
// (model::study::StudySession, as `nibrig experiment run` drives it at a terminal). The
// experimenter fills in the study folder, the stimulus list and the participant ID; the stimuli's
// sounds are made in the background; then the window shows the participant nothing but the study
// (the panel hides its menu, tabs and status): instructions and consent, each trial's Reference, A
// and B to feel as often as wanted (buttons or keys R, A, B), the answer (1, 2), rests, the end.
// Every answer is on disk when its button is pressed; Stop (Esc) ends the session, Resume continues.
// In rig mode the stimuli are physical tools on the turntable (the rig view's simulated or USB rig):
// each one asked for is mounted (the window tells the operator, who confirms) and swept on a worker
// thread while the window shows that the turntable runs; the UI thread never waits for it.
// A rehearsal (the form names a space) runs the same session with a simulated participant answering
// from that space (rig/study/study_rehearsal), paced as a person would be or faster, nothing played on the
// actuator: the experimenter watches every screen and gets the files a person would leave.
#pragma once

#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "model/design/tool_sound.hpp"
#include "model/study/simulated_participant.hpp"
#include "model/study/study_session.hpp"
#include "rig/rig_request.hpp"
#include "rig/study/study_start.hpp"
#include "ui/panel/background_job.hpp"
#include "ui/panel/panel_audio.hpp"
#include "ui/panel/study_plan_preview.hpp"

namespace nibrig::ui::panel {

class ExperimentView {
 public:
  // sound_options: where the stimuli's sounds come from (the panel's catalog and forcing model);
  // rig: the rig a study in rig mode runs (the rig view's choice), or why there is none.
  using RigChoiceRequest = std::function<rig::RigRequest()>;
  ExperimentView(PanelAudio& audio, std::function<model::design::ToolSoundOptions()> sound_options,
                 RigChoiceRequest rig = {});
  ~ExperimentView();

  enum class Stage { setup, preparing, consent, trial, presenting, rest, done };
  Stage stage() const { return stage_; }
  // While a participant is in session (consent to the end): the panel shows nothing else.
  bool fullscreen() const { return stage_ != Stage::setup && stage_ != Stage::preparing; }
  void draw();

  // The setup form, as the experimenter fills it in.
  struct Form {
    std::string study, stimuli, participant;
    int mode = 0;  // 0 actuator, 1 validation (designs against the first stimulus), 2 rig
    bool adaptive = false;
    int practice = 3, break_every = 100;
    bool resume = false;
    int trials = 0;  // main trials; 0: the plan's own size
    std::string rehearse;  // a space: a simulated participant answers from it; empty: a person
    double pace = 20.0;    // rehearsal: its modelled response times divided by this; 0: no waiting
  };
  Form& form() { return form_; }
  // What the buttons and keys do.
  void start();                      // setup → preparing (errors stay in setup, shown)
  void agree(bool yes);              // consent → trial, or back to setup
  void play(model::study::Role role);
  // response_s: the session measures it from the trial's start when not given (a person).
  void answer(model::space::Choice choice, std::optional<double> response_s = std::nullopt);
  void go_on();                      // rest → trial
  // Rig mode: what the operator is asked to do now (empty: nothing), and their confirmation.
  std::string operator_request() const;
  void operator_done();
  std::string operator_notice() const;
  void stop();                       // any stage → setup; the trial in progress is not kept
  // Called every frame by draw(); tests call it while they wait for the sounds.
  void poll();

  const std::string& error() const { return error_; }
  const model::study::StudySession* session() const { return session_.get(); }
  // True while the session in progress is a rehearsal (a simulated participant answers).
  bool rehearsing() const { return rehearsal_ != nullptr; }
  // The plan of the form as it is now; nullptr while it is being worked out (draw() starts that).
  const PlanPreview* plan() const;
  // What the preparing stage's bar says: what is being made, which of how many.
  std::string preparing_label() const;

 private:
  model::study::StudySettings study_settings() const;  // of the form
  PlanRequest plan_request() const;                         // of the form
  void refresh_plan();
  void draw_setup();
  void draw_participant();
  void handle_keys();
  void rehearse_step();  // the simulated participant's next move, timed by the frames

  // What the start's job hands the UI: the checked start and, in a rehearsal, who answers.
  struct Prepared {
    std::shared_ptr<rig::StudyStart> start;
    std::shared_ptr<model::study::SimulatedParticipant> rehearsal;
  };

  // The rig's worker asks the operator through this and waits; the UI answers, never waits.
  struct OperatorDesk {
    mutable std::mutex mutex;
    std::condition_variable changed;
    std::string request, notice;
    bool done = false, abandoned = false;
  };
  // A session stopped while the turntable ran: kept until its sweep ends on its own thread.
  // The job is declared last so that it is destroyed (joined) first, before what it uses.
  struct Retired {
    std::unique_ptr<model::study::Presenter> presenter;
    std::unique_ptr<model::study::StudySession> session;
    std::shared_ptr<OperatorDesk> desk;
    std::unique_ptr<BackgroundJob<bool>> job;
  };

  PanelAudio& audio_;
  std::function<model::design::ToolSoundOptions()> sound_options_;
  RigChoiceRequest rig_;
  Form form_;
  Stage stage_ = Stage::setup;
  std::string error_;
  // The checked start, its folder and sounds prepared on the job; readied in poll().
  std::unique_ptr<BackgroundJob<Prepared>> sounds_job_;
  // Sounds cancelled while one was being made: they end on their own thread (the UI does not wait
  // for the sound in progress) and are dropped once done.
  std::vector<std::unique_ptr<BackgroundJob<Prepared>>> cancelled_sounds_;
  // The form's plan: one job at a time; when the form changed meanwhile, the next starts after it.
  std::unique_ptr<BackgroundJob<PlanPreview>> plan_job_;
  PlanRequest plan_job_for_;
  std::optional<PlanPreview> plan_;
  std::optional<PlanRequest> plan_for_;  // what plan_ is the plan of
  std::unique_ptr<model::study::Presenter> presenter_;
  std::unique_ptr<model::study::StudySession> session_;
  std::unique_ptr<BackgroundJob<bool>> present_job_;  // rig mode: the sweep being run
  // A rehearsal: who answers, and the trial it is in (its plays in order, the next at next_at).
  struct RehearsedTrial {
    std::size_t trial = 0;
    model::study::Answer answer;
    std::vector<model::study::Role> plays;
    std::size_t played = 0;
    std::chrono::steady_clock::duration each{};
    std::chrono::steady_clock::time_point next_at;
  };
  std::shared_ptr<model::study::SimulatedParticipant> rehearsal_;
  std::optional<RehearsedTrial> rehearsed_;
  std::shared_ptr<OperatorDesk> desk_ = std::make_shared<OperatorDesk>();
  std::vector<Retired> retired_;
  char study_text_[512] = "", stimuli_text_[512] = "", participant_text_[65] = "", rehearse_text_[512] = "";
};

}  // namespace nibrig::ui::panel
