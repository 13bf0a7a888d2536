#include "ui/panel/experiment_view.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>

#include "imgui.h"
#include "rig/study/study_rehearsal.hpp"
#include "ui/panel/widgets.hpp"

namespace nibrig::ui::panel {

namespace study = model::study;

ExperimentView::ExperimentView(PanelAudio& audio,
                               std::function<model::design::ToolSoundOptions()> sound_options,
                               RigChoiceRequest rig)
    : audio_(audio), sound_options_(std::move(sound_options)), rig_(std::move(rig)) {}

ExperimentView::~ExperimentView() {
  stop();
  retired_.clear();  // joins a sweep still running (at most its 3 s)
  if (audio_.audition_lent()) audio_.give_back_audition();
}

std::string ExperimentView::operator_request() const {
  std::lock_guard lock(desk_->mutex);
  return desk_->done ? std::string() : desk_->request;
}

std::string ExperimentView::operator_notice() const {
  std::lock_guard lock(desk_->mutex);
  return desk_->notice;
}

void ExperimentView::operator_done() {
  {
    std::lock_guard lock(desk_->mutex);
    desk_->done = true;
  }
  desk_->changed.notify_all();
}

study::StudySettings ExperimentView::study_settings() const {
  study::StudySettings settings;
  settings.study = form_.study;
  settings.participant = form_.participant;
  settings.resume = form_.resume;
  settings.respondent = "a person (the panel)";
  settings.resume_named = "\"resume this participant\" (ticked)";
  return settings;
}

PlanRequest ExperimentView::plan_request() const {
  PlanRequest r;
  r.study = form_.study;
  r.stimuli = form_.stimuli;
  r.mode = form_.mode == 1   ? study::StudyMode::validation
           : form_.mode == 2 ? study::StudyMode::rig
                             : study::StudyMode::actuator;
  r.plan = form_.adaptive ? study::PlanKind::adaptive : study::PlanKind::two_stage;
  r.trials = static_cast<std::size_t>(form_.trials);
  r.practice = static_cast<std::size_t>(form_.practice);
  r.break_every = static_cast<std::size_t>(form_.break_every);
  return r;
}

namespace {

// The form's field a refused start points at.
const char* experiment_form_field(rig::StudyStartRefused::Field field) {
  switch (field) {
    case rig::StudyStartRefused::Field::participant: return "participant ID";
    case rig::StudyStartRefused::Field::definition: return "stimulus list";
    case rig::StudyStartRefused::Field::folder: return "study folder";
    case rig::StudyStartRefused::Field::stimulus: return "stimulus list";
    case rig::StudyStartRefused::Field::rig: return "mode";
  }
  return "form";
}

}  // namespace

void ExperimentView::start() {
  error_.clear();
  try {
    rig::StudyStartRequest request;
    request.settings = study_settings();
    if (!form_.stimuli.empty()) request.definition = definition_from_list(plan_request());
    // The sounds with a ToolSounds of the start's own: the panel's is busy with what the other
    // views play. The rig's simulation asks it for each stimulus it runs, on the rig's worker.
    request.sounds = sound_options_();
    request.sounds.progress = {};
    const std::filesystem::path rehearse = form_.rehearse;
    // A rehearsal presents nothing on the actuator (no sound is made): the simulated participant
    // hears nothing; on the rig the turntable still runs each stimulus.
    if (rehearse.empty())
      request.audition = [this]() -> playback::LiveAudition& { return audio_.lend_audition(); };
    request.rig = rig_;  // asked for in rig mode only: refuses a rig that cannot present (replay)
    // The rig's worker asks and waits; Stop abandons the desk so that it stops waiting. In a
    // rehearsal nobody mounts: the request is only shown.
    desk_ = std::make_shared<OperatorDesk>();
    request.mount = [desk = desk_, rehearsal = !rehearse.empty()](const std::string& message) {
      std::unique_lock lock(desk->mutex);
      desk->request = message;
      desk->done = rehearsal;
      desk->changed.wait(lock, [&] { return desk->done || desk->abandoned; });
      if (desk->abandoned) throw std::runtime_error("stopped while the operator mounted a tool");
    };
    request.notice = [desk = desk_](const std::string& message) {
      std::lock_guard lock(desk->mutex);
      desk->notice = message;
    };
    // Every refusal here, in the form, before anything is written.
    auto checked = std::make_shared<rig::StudyStart>(std::move(request));
    const bool on_rig = checked->definition().mode == study::StudyMode::rig;
    // The folder, then the sounds (none in rig mode: the rig's simulation makes its own). The bar
    // names the sound being made; Cancel stops the job before the next one.
    sounds_job_ = std::make_unique<BackgroundJob<Prepared>>(
        !rehearse.empty() ? "preparing the rehearsal"
        : on_rig          ? "joining the study"
                          : "making the stimuli's sounds",
        [checked, on_rig, rehearse](JobControl& control) {
          Prepared prepared{checked, nullptr};
          if (!rehearse.empty()) {
            control.message("placing the stimuli in " + rehearse.filename().string());
            prepared.rehearsal = rig::rehearse_from(*checked, rehearse, 0.0).participant;
          }
          const std::vector<study::Stimulus>& stimuli = checked->definition().stimuli;
          const auto making = [&control, &stimuli](std::size_t index) {
            control.message(std::to_string(index + 1) + " of " + std::to_string(stimuli.size()) + " (" +
                            stimuli[index].name + ")");
          };
          if (on_rig || prepared.rehearsal)
            control.message("the study folder");
          else if (!stimuli.empty())
            making(0);
          checked->prepare([&](std::size_t done, std::size_t total) {
            if (control.stop_requested()) throw std::runtime_error("making the stimuli's sounds was cancelled");
            control.progress(static_cast<double>(done) / static_cast<double>(total));
            if (done < total) making(done);
          });
          return prepared;
        });
    stage_ = Stage::preparing;
  } catch (const rig::StudyStartRefused& e) {
    error_ = std::string(experiment_form_field(e.field())) + ": " + e.what();
  } catch (const std::exception& e) {
    error_ = e.what();
  }
}

std::string ExperimentView::preparing_label() const {
  if (!sounds_job_) return {};
  const std::string message = sounds_job_->message();
  return sounds_job_->title() + ": " + (message.empty() ? std::string("starting") : message);
}

const PlanPreview* ExperimentView::plan() const {
  return plan_ && plan_for_ && *plan_for_ == plan_request() ? &*plan_ : nullptr;
}

void ExperimentView::refresh_plan() {
  if (plan_job_ && plan_job_->done()) {
    auto result = plan_job_->take_result();
    if (!result) {
      result.emplace();
      result->problem = plan_job_->error();
    }
    plan_ = std::move(*result);
    plan_for_ = plan_job_for_;
    plan_job_.reset();
  }
  // The form's fields change as they are typed in: the plan follows, one job at a time, each
  // reading the files once (the UI thread reads none).
  const PlanRequest wanted = plan_request();
  if (plan_job_ || (plan_for_ && *plan_for_ == wanted)) return;
  plan_job_for_ = wanted;
  plan_job_ = std::make_unique<BackgroundJob<PlanPreview>>(
      "working out the plan", [wanted](JobControl&) { return preview_plan(wanted); });
}

void ExperimentView::poll() {
  std::erase_if(retired_, [](const Retired& r) { return r.job->done(); });
  std::erase_if(cancelled_sounds_, [](const auto& job) { return job->done(); });
  if (stage_ == Stage::presenting && present_job_ && present_job_->done()) {
    const std::string failed = present_job_->error();
    present_job_.reset();
    stage_ = Stage::trial;
    if (!failed.empty()) {
      stop();
      error_ = failed;  // an unplugged rig, say: every answer before is on disk
      return;
    }
    return;
  }
  if (stage_ != Stage::preparing || !sounds_job_ || !sounds_job_->done()) return;
  const std::string failed = sounds_job_->error();
  auto prepared = sounds_job_->take_result();
  sounds_job_.reset();
  if (!failed.empty() || !prepared) {
    error_ = failed.empty() ? "making the stimuli's sounds was cancelled" : failed;
    stage_ = Stage::setup;
    return;
  }
  try {
    // On the UI thread: the actuator's presenter borrows the panel's audition.
    rig::ReadyStudy ready = prepared->start->ready();
    rehearsal_ = prepared->rehearsal;
    presenter_ = std::move(ready.presenter);
    session_ = std::move(ready.session);
    stage_ = Stage::consent;
  } catch (const std::exception& e) {
    error_ = e.what();
    session_.reset();
    presenter_.reset();
    if (audio_.audition_lent()) audio_.give_back_audition();
    stage_ = Stage::setup;
  }
}

void ExperimentView::agree(bool yes) {
  if (stage_ != Stage::consent) return;
  if (!yes) {
    stop();
    error_ = "the participant declined: nothing was recorded";
    return;
  }
  try {
    session_->begin();
    stage_ = session_->complete() ? Stage::done : Stage::trial;
  } catch (const std::exception& e) {
    error_ = e.what();
    stop();
  }
}

void ExperimentView::play(study::Role role) {
  if (stage_ != Stage::trial) return;
  if (session_->definition().mode != study::StudyMode::rig) return session_->play(role);
  // The turntable runs for seconds (and the operator mounts first): on a worker, the UI drawing on.
  present_job_ = std::make_unique<BackgroundJob<bool>>(
      "the turntable", [session = session_.get(), role](JobControl&) {
        session->play(role);
        return true;
      });
  stage_ = Stage::presenting;
}

void ExperimentView::answer(model::space::Choice choice, std::optional<double> response_s) {
  if (stage_ != Stage::trial) return;
  const std::string& p = session_->plays();
  // Each of the three felt at least once before an answer counts.
  if (p.find('R') == std::string::npos || p.find('A') == std::string::npos ||
      p.find('B') == std::string::npos)
    return;
  try {
    const bool rest = session_->answer(choice, response_s);
    stage_ = session_->complete() ? Stage::done : rest ? Stage::rest : Stage::trial;
  } catch (const std::exception& e) {
    error_ = e.what();
    stop();
  }
}

// The simulated participant acts as a person would at this screen, through the same calls as the
// buttons: agrees, feels the trial's stimuli in its own order at its own pace (the frames time it,
// nothing waits), answers, goes on after a rest. On the rig each play runs on the worker as a
// person's does.
void ExperimentView::rehearse_step() {
  if (!rehearsal_) return;
  if (stage_ == Stage::consent) return agree(true);
  if (stage_ == Stage::rest) return go_on();
  if (stage_ != Stage::trial) return;
  const auto prompt = session_->current();
  if (!prompt) return;
  const auto now = std::chrono::steady_clock::now();
  if (!rehearsed_ || rehearsed_->trial != prompt->number) {
    RehearsedTrial next;
    next.trial = prompt->number;
    next.answer = rehearsal_->answer(*prompt, [&](study::Role r) { next.plays.push_back(r); });
    const double pace = form_.pace;
    const double each = pace > 0 ? next.answer.response_s.value_or(0.0) / pace /
                                       static_cast<double>(std::max<std::size_t>(next.plays.size(), 1))
                                 : 0.0;
    next.each = std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(each));
    next.next_at = now + next.each;
    rehearsed_ = std::move(next);
  }
  RehearsedTrial& t = *rehearsed_;
  if (now < t.next_at) return;
  t.next_at = now + t.each;
  if (t.played < t.plays.size()) return play(t.plays[t.played++]);
  answer(t.answer.choice, t.answer.response_s);  // the modelled time, as `experiment run --simulate` records
}

void ExperimentView::go_on() {
  if (stage_ == Stage::rest) stage_ = Stage::trial;
}

void ExperimentView::stop() {
  {
    std::lock_guard lock(desk_->mutex);
    desk_->abandoned = true;
  }
  desk_->changed.notify_all();
  if (present_job_) {
    // The sweep ends on its own thread; its session and rig live until then.
    retired_.push_back({std::move(presenter_), std::move(session_), desk_, std::move(present_job_)});
  }
  desk_ = std::make_shared<OperatorDesk>();
  if (presenter_) presenter_->pause();
  session_.reset();
  presenter_.reset();
  rehearsal_.reset();
  rehearsed_.reset();  // a stopped trial is asked again: the participant's answers depend on its number
  if (sounds_job_) {
    sounds_job_->cancel();
    cancelled_sounds_.push_back(std::move(sounds_job_));
  }
  if (audio_.audition_lent()) audio_.give_back_audition();
  stage_ = Stage::setup;
  form_.resume = true;  // what the next Start most likely is
  plan_for_.reset();    // answers were added: the measured time per trial changes
}

void ExperimentView::draw() {
  poll();
  if (fullscreen())
    draw_participant();
  else
    draw_setup();
}

void ExperimentView::draw_setup() {
  section("A triplet study, one participant at a time");
  const auto field = [](const char* label, char* text, std::size_t size, std::string& value) {
    std::snprintf(text, size, "%s", value.c_str());
    if (ImGui::InputText(label, text, size)) value = text;
  };
  field("study folder", study_text_, sizeof study_text_, form_.study);
  field("stimulus list (tool/surface a line)", stimuli_text_, sizeof stimuli_text_, form_.stimuli);
  field("participant ID", participant_text_, sizeof participant_text_, form_.participant);
  field("rehearse from space (a simulated participant answers; empty: a person)", rehearse_text_,
        sizeof rehearse_text_, form_.rehearse);
  if (!form_.rehearse.empty()) {
    ImGui::InputDouble("rehearsal pace (times a person's speed; 0: no waiting)", &form_.pace, 0.0, 0.0, "%.1f");
    form_.pace = std::clamp(form_.pace, 0.0, 1e6);
  }
  ImGui::Combo("mode", &form_.mode,
               "actuator\0validation (designs against the first stimulus)\0rig (the rig view's rig)\0");
  ImGui::Checkbox("adaptive plan (else the paper's two stages)", &form_.adaptive);
  ImGui::InputInt("main trials (0: the plan's own size)", &form_.trials);
  ImGui::InputInt("practice trials", &form_.practice);
  ImGui::InputInt("rest every N trials (0: none)", &form_.break_every);
  form_.trials = std::max(0, form_.trials);
  form_.practice = std::max(0, form_.practice);
  form_.break_every = std::max(0, form_.break_every);
  ImGui::Checkbox("resume this participant", &form_.resume);
  ImGui::TextDisabled("Edit instructions.txt and consent.txt in the study folder. Rig mode runs the "
                      "simulated or USB rig chosen in the rig view.");
  refresh_plan();
  if (const PlanPreview* p = plan()) {
    for (const std::string& line : plan_lines(*p)) ImGui::TextWrapped("%s", line.c_str());
  } else {
    ImGui::TextDisabled("working out the plan...");
  }
  if (stage_ == Stage::preparing) {
    if (progress_with_cancel("sounds", static_cast<float>(sounds_job_ ? sounds_job_->progress() : 0.0),
                             preparing_label().c_str()))
      stop();
  } else if (ImGui::Button(!form_.rehearse.empty() ? (form_.resume ? "Resume the rehearsal" : "Rehearse")
                          : form_.resume            ? "Resume"
                                                    : "Start")) {
    start();
  }
  if (!error_.empty()) ImGui::TextColored({1.0f, 0.45f, 0.35f, 1.0f}, "%s", error_.c_str());
}

void ExperimentView::handle_keys() {
  const auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
  if (pressed(GLFW_KEY_ESCAPE)) return stop();
  if (stage_ == Stage::trial) {
    if (pressed(GLFW_KEY_R)) play(study::Role::reference);
    if (pressed(GLFW_KEY_A)) play(study::Role::left);
    if (pressed(GLFW_KEY_B)) play(study::Role::right);
    if (pressed(GLFW_KEY_1)) answer(model::space::Choice::left);
    if (pressed(GLFW_KEY_2)) answer(model::space::Choice::right);
  } else if (stage_ == Stage::rest && (pressed(GLFW_KEY_ENTER) || pressed(GLFW_KEY_SPACE))) {
    go_on();
  }
}

void ExperimentView::draw_participant() {
  handle_keys();
  rehearse_step();
  if (stage_ == Stage::setup) return;  // stopped by a key
  if (rehearsal_)
    ImGui::TextColored({0.95f, 0.75f, 0.30f, 1.0f}, "Rehearsal: a simulated participant answers from %s (Esc stops)",
                       form_.rehearse.c_str());
  const ImVec2 size = ImGui::GetContentRegionAvail();
  const ImVec2 big{size.x / 3.0f - 12.0f, size.y / 4.0f};
  if (stage_ == Stage::consent) {
    ImGui::TextWrapped("%s", session_->texts().instructions.c_str());
    ImGui::Separator();
    ImGui::TextWrapped("%s", session_->texts().consent.c_str());
    if (ImGui::Button("I agree", {size.x / 2.0f - 8.0f, big.y / 2.0f})) agree(true);
    ImGui::SameLine();
    if (ImGui::Button("I do not agree", {size.x / 2.0f - 8.0f, big.y / 2.0f})) agree(false);
    return;
  }
  if (stage_ == Stage::rest || stage_ == Stage::done) {
    const auto& r = session_->result();
    ImGui::Text("%zu trials done.", r.resumed_at + r.answered);
    if (stage_ == Stage::rest) {
      ImGui::TextUnformatted("Take a rest. Go on when you are ready (Enter).");
      if (ImGui::Button("Go on", big)) go_on();
    } else {
      ImGui::TextUnformatted("That was the last trial. Thank you!");
      if (ImGui::Button("Close", big)) stop();
    }
    return;
  }
  if (stage_ == Stage::presenting) {
    const std::string request = operator_request();
    if (!request.empty()) {
      ImGui::Text("Operator: %s", request.c_str());
      if (ImGui::Button("Done", big)) operator_done();
    } else {
      ImGui::TextUnformatted("The turntable runs: draw with the tool now.");
    }
    if (ImGui::SmallButton("Stop for now (Esc)")) stop();
    return;
  }
  const auto prompt = session_->current();
  if (!prompt) return;
  if (session_->definition().mode == study::StudyMode::rig)
    ImGui::TextDisabled("Operator: %s", operator_notice().c_str());
  ImGui::ProgressBar(static_cast<float>(prompt->number - 1) / static_cast<float>(prompt->expected_at_most),
                     {-1.0f, 0.0f},
                     (std::string("trial ") + std::to_string(prompt->number) + " of at most " +
                      std::to_string(prompt->expected_at_most) + (prompt->planned.practice ? " (practice)" : ""))
                         .c_str());
  ImGui::TextUnformatted("Feel the reference, A and B as often as you like, then say which is closer to the reference.");
  const std::string& plays = session_->plays();
  const char last = plays.empty() ? 0 : plays.back();
  const auto role_button = [&](const char* label, study::Role role) {
    const bool on = last == static_cast<char>(role);
    if (on) ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.20f, 0.55f, 0.30f, 1.0f));
    if (ImGui::Button(label, big)) play(role);
    if (on) ImGui::PopStyleColor();
  };
  role_button("Reference (R)", study::Role::reference);
  ImGui::SameLine();
  role_button("A (A)", study::Role::left);
  ImGui::SameLine();
  role_button("B (B)", study::Role::right);
  const bool felt = plays.find('R') != std::string::npos && plays.find('A') != std::string::npos &&
                    plays.find('B') != std::string::npos;
  if (!felt) ImGui::BeginDisabled();
  if (ImGui::Button("A is closer (1)", {size.x / 2.0f - 8.0f, big.y})) answer(model::space::Choice::left);
  ImGui::SameLine();
  if (ImGui::Button("B is closer (2)", {size.x / 2.0f - 8.0f, big.y})) answer(model::space::Choice::right);
  if (!felt) ImGui::EndDisabled();
  if (ImGui::SmallButton("Stop for now (Esc)")) stop();
}

}  // namespace nibrig::ui::panel
