// A capture: a rig runs a speed profile and everything it delivers goes into a session folder
// (model/io/rig_session.hpp) as it arrives, block by block, with the capture record (frames, drops,
// saturation, alignment) kept current in session.json. Killed, crashed or unplugged, the .partial
// folder still reads up to its last block; a finished capture is renamed to its folder.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <stop_token>
#include <string>

#include "model/io/rig_session.hpp"
#include "rig/rig.hpp"

namespace nibrig::rig {

struct CaptureProgress {
  double seconds = 0.0;  // acceleration recorded
  double duration_s = 0.0;  // the profile's length
  double speed_m_s = 0.0;   // the newest frame's
  std::uint64_t dropped_frames = 0;
};

struct CaptureOptions {
  std::filesystem::path folder;  // the session to write (<folder>.partial while recording)
  // What is mounted; empty: what the rig says (a simulated or replayed rig knows).
  std::string tool, surface;
  std::string notes;
  // Called on the capture's thread with every batch as it was written (the live comparison feeds
  // on this), and about once a second with the progress. Either may be empty.
  std::function<void(const RigData&)> on_data;
  std::function<void(const CaptureProgress&)> on_progress;
  // Stopped (Ctrl-C, a window's stop, a Python KeyboardInterrupt): the motor stops and the session
  // is finished with what it holds.
  std::stop_token cancel;
  double record_every_s = 1.0;  // how often session.json's capture record is rewritten
};

struct CaptureResult {
  std::filesystem::path folder;  // where the session is: <folder>, or <folder>.partial
  bool complete = false;         // the profile ran to its end
  model::io::CaptureRecord record;
};

// Throws std::invalid_argument, before any folder exists, when the profile asks more of the motor
// than the rig's range (saying the range) or the tool or surface are unknown; std::runtime_error
// when the session folder exists. A rig that ends early (unplugged, stopped, cancelled) still gives
// a finished session holding everything received, with ended_because saying why.
CaptureResult capture_session(Rig& rig, const SpeedProfile& profile, const CaptureOptions& options);

// The session header a capture writes for this rig and profile (tool, surface, rates, units,
// calibration, profile points).
model::io::RigSessionInfo session_info_for(const RigDescription& rig, const SpeedProfile& profile,
                                        const CaptureOptions& options);

}  // namespace nibrig::rig
