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
#include "ui/panel/stroke_choice.hpp"

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

// What `open` asks of the back end for `device`, under the JACK client name `stream_name`.
playback::OutputSettings output_settings_of(const DeviceRequest& device, std::string stream_name);

class PanelAudio {
 public:
  explicit PanelAudio(model::design::ToolSoundOptions sounds);
  ~PanelAudio();

  // Opens the device (the audition keeps playing what it played). Returns the error, if any.
  std::string open(const DeviceRequest& device);
  void close();
  // The device open now, as it was asked for; nullopt when none is.
  const std::optional<DeviceRequest>& device() const { return device_; }
  const playback::LiveAudition& audition() const { return audition_; }
  // Plays through a stored actuator calibration (by name) or an actuator file from now on.
  // Returns the error, if any.
  std::string use_actuator(const std::string& name_or_file);

  // The panel's one stroke: every view plays it. After it is edited, stroke_changed() makes what
  // sounds follow it at once (a tool stroked keeps sounding under the new stroke); a stroke that
  // cannot be made (a trajectory file that does not read) is an error and changes nothing.
  StrokeChoice& stroke() { return stroke_choice_; }
  const StrokeChoice& stroke() const { return stroke_choice_; }
  void stroke_changed();

  // Plays these one to three tools (slot i = tools[i], the first selected) with the stroke: their
  // sounds are made in the background and loaded when ready (poll()). `at_rest`: loaded and held
  // still instead, for a live contact (the pad) to move.
  void play(const std::vector<ToolChoice>& tools, bool at_rest = false);
  // Plays `sound` at once in slot 0 (built here: about a millisecond), crossfaded from what played;
  // what moves the engine keeps moving it, or the stroke starts when nothing did. The design
  // view's path: its sounds come from the design-response grid, not from ToolSounds.
  void play_now(const model::design::ToolSound& sound);
  // Switches to slot i of what is playing (A/B, triplet).
  void select(std::size_t slot);
  // A live contact (the pad): replaces the stroke until play() attaches one again.
  void contact(double speed_m_s, double force_n);
  // Silence: the engine is held at rest until something is played again.
  void stop();
  // What is loaded plays again under the stroke (after stop(), or the pad let go): what the
  // status line's "Enter plays again" promises when no tool is chosen in the space view.
  void play_again();

  // Called every frame: loads the sounds that are ready. Never blocks.
  void poll();
  // Commands the engine's queue has not taken yet: poll() must run again soon to hand them over.
  bool handing_over() const { return waiting_commands_ > 0; }
  bool making_sounds() const { return job_ != nullptr || pending_.has_value(); }
  // Drops the sounds being made (the Cancel beside their bar); what plays keeps playing.
  void cancel_making();
  double making_progress() const { return job_ ? job_->progress() : 1.0; }
  std::string making_message() const { return job_ ? job_->message() : std::string(); }
  // What is loaded and playing (slot order), and the last error (a tool refused, a device lost).
  const std::vector<ToolChoice>& playing() const { return playing_; }
  const std::vector<std::string>& names() const { return audition_.names(); }
  const std::string& error() const { return error_; }
  // What moves the engine: the stroke's description, "the pad", or "stopped".
  std::string stroke_description() const;
  // The tool heard now (the selected slot): none when stopped, nothing is loaded, the pad is
  // not pressed, or no device is running (none open, or lost: a dead JACK server).
  std::optional<ToolChoice> sounding() const;
  // The stroke chosen, in words ("constant 250.00 mm/s", "sweep ..."), whether or not it plays.
  const std::string& chosen_stroke_description() const { return chosen_description_; }

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
  // What moves the engine now.
  enum class Driver { none, stroke, pad };
  void start_pending();
  void attach_stroke();
  playback::LiveAudition audition_;
  std::optional<DeviceRequest> device_;
  std::shared_ptr<model::design::ToolSounds> sounds_;  // shared with the job that uses it
  std::unique_ptr<BackgroundJob<Sounds>> job_;
  std::vector<std::unique_ptr<BackgroundJob<Sounds>>> retired_;  // superseded by use_sounds, finishing
  struct Request {
    std::vector<ToolChoice> tools;
    bool at_rest = false;
  };
  std::optional<Request> pending_;
  bool requested_at_rest_ = false;
  std::vector<ToolChoice> requested_, playing_;
  StrokeChoice stroke_choice_;
  Driver driver_ = Driver::none;
  bool pad_pressing_ = false;  // the pad's last contact had speed and force
  std::string stroke_description_, chosen_description_;
  std::string error_;
  std::uint64_t seed_ = 1;
  bool lent_ = false;
  std::size_t waiting_commands_ = 0;
};

}  // namespace nibrig::ui::panel
