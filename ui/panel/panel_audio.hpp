// What the panel plays, and on what: the live audition (playback/live_audition.hpp) on the device a
// person chose, and the tools' sounds (model::design::ToolSounds), made on a worker thread because
// the first one meshes the stylus and a design point may fit the forcing model first. The UI thread
// asks and looks; it never waits for a sound to be made nor for the audio thread.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "model/design/tool_sound.hpp"
#include "playback/live_audition.hpp"
#include "rt/stroke_request.hpp"
#include "ui/panel/background_job.hpp"

namespace nibrig::ui::panel {

// A tool on a surface, as a person picks it: a catalog tool id or a design point.
struct ToolChoice {
  std::string tool;
  std::string surface;
  bool operator==(const ToolChoice&) const = default;
};

struct DeviceRequest {
  std::string api;     // "jack", "alsa", "pulse"; empty: the first with an output
  std::string device;  // by name; empty: the default
  unsigned output_channel = 1;
  unsigned period_frames = 256;
};

class PanelAudio {
 public:
  explicit PanelAudio(model::design::ToolSoundOptions sounds);
  ~PanelAudio();

  // Opens the device (the audition keeps playing what it played). Returns the error, if any.
  std::string open(const DeviceRequest& device);
  void close();
  const playback::LiveAudition& audition() const { return audition_; }
  // Plays through a stored actuator calibration (by name) or an actuator file from now on.
  // Returns the error, if any.
  std::string use_actuator(const std::string& name_or_file);

  // Plays these one to three tools (slot i = tools[i], the first selected) with `stroke`: their
  // sounds are made in the background and loaded when ready (poll()).
  void play(const std::vector<ToolChoice>& tools, const rt::StrokeRequest& stroke);
  // Plays `sound` at once in slot 0 (built here: about a millisecond), crossfaded from what played;
  // the stroke keeps running, or `stroke` starts when nothing was moving the engine. The design
  // view's path: its sounds come from the design-response grid, not from ToolSounds.
  void play_now(const model::design::ToolSound& sound, const rt::StrokeRequest& stroke);
  // Switches to slot i of what is playing (A/B, triplet).
  void select(std::size_t slot);
  // A live contact (the pad): replaces the stroke until play() attaches one again.
  void contact(double speed_m_s, double force_n);
  void stop();

  // Called every frame: loads the sounds that are ready. Never blocks.
  void poll();
  bool making_sounds() const { return job_ != nullptr || pending_.has_value(); }
  double making_progress() const { return job_ ? job_->progress() : 1.0; }
  std::string making_message() const { return job_ ? job_->message() : std::string(); }
  // What is loaded and playing (slot order), and the last error (a tool refused, a device lost).
  const std::vector<ToolChoice>& playing() const { return playing_; }
  const std::vector<std::string>& names() const { return audition_.names(); }
  const std::string& error() const { return error_; }
  std::string stroke_description() const { return stroke_description_; }

  // Lends the audition to the experiment view, which loads and plays a trial's three stimuli in
  // its slots while a participant is in session: what played stops and sounds still being made are
  // dropped, and nothing is loaded again until it is given back.
  playback::LiveAudition& lend_audition();
  void give_back_audition() { lent_ = false; }
  bool audition_lent() const { return lent_; }

  // The catalog the sounds come from (read when constructed).
  const model::io::Catalog& catalog() const { return sounds_->catalog(); }
  // Sounds come from `sounds` from now on (another catalog or forcing model, opened in the window);
  // what plays keeps playing. A sound being made with the old ones finishes on its own thread and
  // is dropped: the UI does not wait for it.
  void use_sounds(std::shared_ptr<model::design::ToolSounds> sounds);

 private:
  using Sounds = std::vector<model::design::ToolSound>;
  struct Request {
    std::vector<ToolChoice> tools;
    rt::StrokeRequest stroke;
  };
  void start_pending();
  playback::LiveAudition audition_;
  std::shared_ptr<model::design::ToolSounds> sounds_;  // shared with the job that uses it
  std::unique_ptr<BackgroundJob<Sounds>> job_;
  std::vector<std::unique_ptr<BackgroundJob<Sounds>>> retired_;  // superseded by use_sounds, finishing
  std::optional<Request> pending_;
  std::vector<ToolChoice> requested_, playing_;
  rt::StrokeRequest stroke_;
  std::string stroke_description_;
  std::string error_;
  std::uint64_t seed_ = 1;
  bool lent_ = false;
};

}  // namespace nibrig::ui::panel
