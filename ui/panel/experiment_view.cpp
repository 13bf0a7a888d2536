#include "ui/panel/experiment_view.hpp"

#include <GLFW/glfw3.h>

#include <cstdio>
#include <cstring>

#include "imgui.h"
#include "model/io/bundled_assets.hpp"
#include "ui/panel/widgets.hpp"

namespace nibrig::ui::panel {

namespace study = model::study;

ExperimentView::ExperimentView(PanelAudio& audio,
                               std::function<model::design::ToolSoundOptions()> sound_options)
    : audio_(audio), sound_options_(std::move(sound_options)) {}

ExperimentView::~ExperimentView() {
  if (audio_.audition_lent()) audio_.give_back_audition();
}

void ExperimentView::start() {
  error_.clear();
  try {
    study::SessionSettings settings;
    settings.study = form_.study;
    settings.participant = form_.participant;
    settings.resume = form_.resume;
    settings.respondent = "a person (the panel)";
    study::check_participant_id(form_.participant);
    if (!form_.resume || !form_.stimuli.empty()) {
      if (form_.stimuli.empty()) throw std::invalid_argument("a new study needs its stimulus list");
      study::StudyDefinition d;
      d.stimuli = study::read_stimulus_list(form_.stimuli);
      d.plan = form_.adaptive ? study::PlanKind::adaptive : study::PlanKind::two_stage;
      d.practice = static_cast<std::size_t>(form_.practice);
      d.break_every = static_cast<std::size_t>(form_.break_every);
      if (std::filesystem::exists(std::filesystem::path(form_.study) / study::kStudyFile))
        study::check_session(settings);  // a taken ID is refused before the study is touched
      // An unknown tool or surface too (reading the catalog takes milliseconds; no meshing).
      rig::check_study_stimuli(model::design::ToolSounds(sound_options_()), d.stimuli);
      study::create_or_join_study(form_.study, d, model::io::asset("experiment/instructions.txt"),
                                  model::io::asset("experiment/consent.txt"));
    }
    study::check_session(settings);
    const std::vector<study::Stimulus> stimuli =
        study::read_study_file(std::filesystem::path(form_.study) / study::kStudyFile).stimuli;
    auto options = sound_options_();
    options.progress = {};
    // The sounds with a ToolSounds of its own: the panel's is busy with what the other views play.
    sounds_job_ = std::make_unique<BackgroundJob<std::vector<model::design::ToolSound>>>(
        "making the stimuli's sounds", [options, stimuli](JobControl& control) {
          model::design::ToolSounds sounds(options);
          rig::check_study_stimuli(sounds, stimuli);
          return rig::study_sounds(sounds, stimuli, [&control](std::size_t done, std::size_t total) {
            control.progress(static_cast<double>(done) / static_cast<double>(total));
            control.message("made " + std::to_string(done) + " of " + std::to_string(total));
          });
        });
    stage_ = Stage::preparing;
  } catch (const std::exception& e) {
    error_ = e.what();
  }
}

void ExperimentView::poll() {
  if (stage_ != Stage::preparing || !sounds_job_ || !sounds_job_->done()) return;
  const std::string failed = sounds_job_->error();
  auto sounds = sounds_job_->take_result();
  sounds_job_.reset();
  if (!failed.empty() || !sounds) {
    error_ = failed.empty() ? "making the stimuli's sounds was cancelled" : failed;
    stage_ = Stage::setup;
    return;
  }
  try {
    study::SessionSettings settings;
    settings.study = form_.study;
    settings.participant = form_.participant;
    settings.resume = form_.resume;
    settings.respondent = "a person (the panel)";
    presenter_ = std::make_unique<rig::ActuatorPresenter>(audio_.lend_audition(), std::move(*sounds));
    session_ = std::make_unique<study::StudySession>(settings, *presenter_);
    stage_ = Stage::consent;
  } catch (const std::exception& e) {
    error_ = e.what();
    presenter_.reset();
    audio_.give_back_audition();
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
  if (stage_ == Stage::trial) session_->play(role);
}

void ExperimentView::answer(model::space::Choice choice) {
  if (stage_ != Stage::trial) return;
  const std::string& p = session_->plays();
  // Each of the three felt at least once before an answer counts.
  if (p.find('R') == std::string::npos || p.find('A') == std::string::npos ||
      p.find('B') == std::string::npos)
    return;
  try {
    const bool rest = session_->answer(choice);
    stage_ = session_->complete() ? Stage::done : rest ? Stage::rest : Stage::trial;
  } catch (const std::exception& e) {
    error_ = e.what();
    stop();
  }
}

void ExperimentView::go_on() {
  if (stage_ == Stage::rest) stage_ = Stage::trial;
}

void ExperimentView::stop() {
  if (presenter_) presenter_->pause();
  session_.reset();
  presenter_.reset();
  sounds_job_.reset();
  if (audio_.audition_lent()) audio_.give_back_audition();
  stage_ = Stage::setup;
  form_.resume = true;  // what the next Start most likely is
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
  ImGui::Checkbox("adaptive plan (else the paper's two stages)", &form_.adaptive);
  ImGui::InputInt("practice trials", &form_.practice);
  ImGui::InputInt("rest every N trials (0: none)", &form_.break_every);
  form_.practice = std::max(0, form_.practice);
  form_.break_every = std::max(0, form_.break_every);
  ImGui::Checkbox("resume this participant", &form_.resume);
  ImGui::TextDisabled("Edit instructions.txt and consent.txt in the study folder. Rig mode: `nibrig "
                      "experiment run --mode rig` at the rig's terminal.");
  if (stage_ == Stage::preparing) {
    if (progress_with_cancel("sounds", static_cast<float>(sounds_job_ ? sounds_job_->progress() : 0.0),
                             sounds_job_ ? sounds_job_->message().c_str() : ""))
      stop();
  } else if (ImGui::Button(form_.resume ? "Resume" : "Start")) {
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
  if (stage_ == Stage::setup) return;  // stopped by a key
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
  const auto prompt = session_->current();
  if (!prompt) return;
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
