// The live player: one engine with a voice per slot (a tool, or the two or three of an A/B or
// triplet comparison), a stroke or a live contact, on a device by name or on none at all (a
// screenshot, a machine without audio), its tools and slot changed while it plays. No call waits
// for the audio thread: what the engine's queue cannot take yet is held and handed over by a later
// call or pump(). An engine rendered to a file instead is a PreparedEngine (prepared_engine.hpp).
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "model/modal/voice_source.hpp"
#include "playback/actuator_file.hpp"
#include "playback/audio_output.hpp"
#include "rt/engine.hpp"
#include "rt/stroke_source.hpp"

namespace nibrig::playback {

class LiveAudition {
 public:
  // An engine with settings.slots slots (at least one), silent until a voice is loaded and a stroke
  // or contact moves it. Throws what rt::Engine throws for bad settings.
  explicit LiveAudition(rt::EngineSettings settings);
  ~LiveAudition();
  LiveAudition(const LiveAudition&) = delete;
  LiveAudition& operator=(const LiveAudition&) = delete;

  // Plays on that device from now on (closing any other first). Throws DeviceError naming what was
  // asked; the audition then plays nowhere, as before open.
  void open(const OutputSettings& output);
  void close();
  bool playing_on_a_device() const noexcept { return output_ != nullptr; }
  // Of the open device; nullopt when none is open.
  std::optional<StreamInfo> stream_info() const;
  std::optional<OutputStats> output_stats() const;
  std::optional<OutputStatus> output_status() const;
  std::string last_problem() const;

  // The voice of `voice` (built here, on the calling thread: milliseconds) into `slot`, crossfaded
  // in when `slot` is the one selected. Throws std::invalid_argument for a slot out of range and
  // what rt::build_voice throws.
  void load(std::size_t slot, const model::modal::VoiceSource& voice, std::uint64_t seed);
  void select(std::size_t slot);
  std::size_t selected() const noexcept { return selected_; }
  // The name of the voice in each slot ("" for none yet).
  const std::vector<std::string>& names() const noexcept { return names_; }
  // A stroke to follow (constant, sweep, trajectory: rt/stroke_request.hpp), or a live contact
  // (the pad, the rig): each replaces the other.
  void attach(std::unique_ptr<rt::StrokeSource> stroke);
  void set_contact(double speed_m_s, double normal_force_n);
  // Through the actuator's inverse filter from now on (the output level becomes a trim), as
  // PreparedEngine::use_actuator; returns the filter, whose flatness a face shows. `name` says
  // which calibration is in use (actuator()).
  InverseFilter use_actuator(const ActuatorCalibration& calibration, std::string name);
  const std::string& actuator() const noexcept { return actuator_; }
  rt::EngineStats engine_stats() const { return engine_->stats(); }
  // Hands over what the engine's queue refused before (call it regularly, e.g. once a frame); how
  // many commands still wait.
  std::size_t pump();
  double sample_rate() const noexcept { return engine_->sample_rate(); }

 private:
  // Hands commands to the engine in order, without ever waiting for the audio thread: what its
  // queue refuses (full: the callback has not run since, or the device is lost) waits here and is
  // handed over by the next call or pump(). With no device open, nothing else calls the engine, so
  // this thread renders a block into scratch to drain the queue.
  struct Pending {
    bool contact = false;             // a live contact: a newer one replaces it
    std::function<bool()> command;    // true once the engine took it
  };
  void deliver(Pending pending);

  std::deque<Pending> pending_;
  std::unique_ptr<rt::Engine> engine_;
  std::unique_ptr<AudioOutput> output_;
  std::vector<std::string> names_;
  std::string actuator_;
  std::size_t selected_ = 0;
  std::vector<float> scratch_;
};

}  // namespace nibrig::playback
