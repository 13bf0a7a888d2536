#include "ui/panel/panel_audio.hpp"

#include <stdexcept>

#include "playback/actuator_file.hpp"
#include "playback/actuator_store.hpp"

namespace nibrig::ui::panel {

PanelAudio::PanelAudio(model::design::ToolSoundOptions sounds)
    : audition_(rt::EngineSettings{}),
      sounds_(std::make_shared<model::design::ToolSounds>(std::move(sounds))) {
  chosen_description_ = rt::make_stroke(stroke_choice_.request()).description;
}

PanelAudio::~PanelAudio() {
  job_.reset();  // stops and joins the job before the sounds it uses go
  retired_.clear();
}

void PanelAudio::use_sounds(std::shared_ptr<model::design::ToolSounds> sounds) {
  if (job_) {
    job_->cancel();
    retired_.push_back(std::move(job_));
  }
  pending_.reset();
  sounds_ = std::move(sounds);
}

playback::OutputSettings output_settings_of(const DeviceRequest& device, std::string stream_name) {
  playback::OutputSettings settings;
  settings.api = device.api;
  settings.device = device.device;
  settings.output_channel = device.output_channel;
  settings.period_frames = device.period_frames;
  settings.stream_name = std::move(stream_name);
  return settings;
}

std::string PanelAudio::open(const DeviceRequest& device) {
  device_.reset();
  try {
    audition_.open(output_settings_of(device, "nibrig-panel"));
    device_ = device;
    return {};
  } catch (const std::exception& e) {
    error_ = e.what();
    return error_;
  }
}

void PanelAudio::close() {
  audition_.close();
  device_.reset();
}

std::string PanelAudio::use_actuator(const std::string& name_or_file) {
  try {
    const auto file = playback::find_actuator(name_or_file);
    audition_.use_actuator(playback::read_actuator_file(file), file.string());
    return {};
  } catch (const std::exception& e) {
    return e.what();
  }
}

void PanelAudio::stroke_changed() {
  try {
    rt::Stroke made = rt::make_stroke(stroke_choice_.request());  // a bad trajectory file, said now
    chosen_description_ = made.description;
    if (driver_ != Driver::stroke || lent_) return;
    stroke_description_ = std::move(made.description);
    audition_.attach(std::move(made.source));
    error_.clear();
  } catch (const std::exception& e) {
    error_ = e.what();
  }
}

void PanelAudio::attach_stroke() {
  rt::Stroke made = rt::make_stroke(stroke_choice_.request());
  stroke_description_ = made.description;
  audition_.attach(std::move(made.source));
  driver_ = Driver::stroke;
}

void PanelAudio::play(const std::vector<ToolChoice>& tools, bool at_rest) {
  if (tools.empty() || tools.size() > audition_.names().size()) {
    error_ = "choose one to " + std::to_string(audition_.names().size()) + " tools to play";
    return;
  }
  error_.clear();
  try {  // refused before any meshing: a pairing the catalog lacks, a malformed design point
    for (const auto& t : tools) sounds_->check(t.tool, t.surface);
    rt::make_stroke(stroke_choice_.request());  // a bad trajectory file or speed, said now
  } catch (const std::exception& e) {
    error_ = e.what();
    return;
  }
  // One job at a time (ToolSounds loads its stylus and forcing model lazily, on one thread): a
  // request made while sounds are being made waits for them, and only the newest waiting one runs.
  pending_ = Request{tools, at_rest};
  start_pending();
}

void PanelAudio::start_pending() {
  if (job_ || !pending_) return;
  requested_ = pending_->tools;
  requested_at_rest_ = pending_->at_rest;
  const auto tools = pending_->tools;
  pending_.reset();
  auto sounds = sounds_;
  job_ = std::make_unique<BackgroundJob<Sounds>>(
      "making the tools' sounds", [sounds, tools](JobControl& control) {
        Sounds made;
        for (std::size_t i = 0; i < tools.size() && !control.stop_requested(); ++i) {
          const std::string what = tools[i].tool + " on " + tools[i].surface;
          if (model::design::names_design_point(tools[i].tool))
            control.message("predicting " + what + " (the design's FEM: about a second)");
          else if (sounds->solves_stylus_modes())
            control.message("making " + what + ": solving the stylus's modes first (once: they are kept)");
          else
            control.message("making " + what);
          made.push_back(sounds->sound(tools[i].tool, tools[i].surface));
          control.progress(static_cast<double>(i + 1) / static_cast<double>(tools.size()));
        }
        return made;
      });
}

void PanelAudio::cancel_making() {
  if (job_) {
    job_->cancel();
    retired_.push_back(std::move(job_));
  }
  pending_.reset();
}

void PanelAudio::poll() {
  waiting_commands_ = audition_.pump();  // what the engine's queue could not take last frame
  std::erase_if(retired_, [](const auto& job) { return job->done(); });
  if (lent_) return;
  if (!job_ || !job_->done()) return;
  const std::string failed = job_->error();
  auto made = job_->take_result();
  job_.reset();
  if (pending_) {  // superseded while it was being made: make the newest instead
    start_pending();
    return;
  }
  if (!failed.empty() || !made || made->size() != requested_.size()) {
    error_ = failed.empty() ? "making the sounds was cancelled" : failed;
    return;
  }
  try {
    for (std::size_t i = 0; i < made->size(); ++i)
      audition_.load(i, (*made)[i], seed_ + i);
    audition_.select(0);
    if (requested_at_rest_) contact(0.0, 0.0);
    else attach_stroke();  // the stroke as it is now, though it changed while the sounds were made
    playing_ = requested_;
  } catch (const std::exception& e) {
    error_ = e.what();
  }
}

void PanelAudio::play_now(const model::design::ToolSound& sound) {
  try {
    audition_.load(0, sound, seed_);
    if (audition_.selected() != 0) audition_.select(0);
    if (driver_ == Driver::none) attach_stroke();
    playing_ = {ToolChoice{sound.name, ""}};
    error_.clear();
  } catch (const std::exception& e) {
    error_ = e.what();
  }
}

void PanelAudio::select(std::size_t slot) {
  if (slot >= playing_.size()) return;
  try {
    audition_.select(slot);
  } catch (const std::exception& e) {
    error_ = e.what();
  }
}

void PanelAudio::contact(double speed_m_s, double force_n) {
  try {
    audition_.set_contact(speed_m_s, force_n);
    driver_ = Driver::pad;
    pad_pressing_ = speed_m_s > 0.0 && force_n > 0.0;
  } catch (const std::exception& e) {
    error_ = e.what();
  }
}

void PanelAudio::stop() {
  try {
    audition_.set_contact(0.0, 0.0);  // at rest: the voices ring out and fall silent
    driver_ = Driver::none;
  } catch (const std::exception& e) {
    error_ = e.what();
  }
}

std::string PanelAudio::stroke_description() const {
  switch (driver_) {
    case Driver::stroke: return stroke_description_;
    case Driver::pad: return "the pad";
    case Driver::none: break;
  }
  return "stopped";
}

void PanelAudio::play_again() {
  if (playing_.empty() || lent_) return;
  try {
    attach_stroke();
  } catch (const std::exception& e) {
    error_ = e.what();
  }
}

std::optional<ToolChoice> PanelAudio::sounding() const {
  if (driver_ == Driver::none || lent_) return std::nullopt;
  if (driver_ == Driver::pad && !pad_pressing_) return std::nullopt;
  if (audition_.output_status() != playback::OutputStatus::running) return std::nullopt;
  const std::size_t slot = audition_.selected();
  if (slot >= playing_.size()) return std::nullopt;
  return playing_[slot];
}

playback::LiveAudition& PanelAudio::lend_audition() {
  stop();
  if (job_) {
    job_->cancel();
    retired_.push_back(std::move(job_));
  }
  pending_.reset();
  requested_.clear();
  playing_.clear();
  lent_ = true;
  return audition_;
}

}  // namespace nibrig::ui::panel
