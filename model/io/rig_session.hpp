// Our own rig recording format: a folder with session.json (what, how, calibration) and one float32
// WAV file per stream. Written incrementally into <folder>.partial and renamed on finish, so a
// capture that is killed still leaves every block recorded up to that point readable.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace nibrig::model::io {

// How a capture went: which rig recorded it and what went wrong on the way. The capture keeps it
// current in session.json while recording (RigSessionWriter::update_capture), so a capture cut short
// still says how much it kept and why it ended.
struct CaptureRecord {
  std::string rig;                    // "simulated rig, seed 1", "USB rig controller NR-0001"
  double seconds = 0.0;               // acceleration recorded, in seconds
  std::uint64_t frames = 0;           // sensor frames received
  std::uint64_t dropped_frames = 0;   // lost on the way (gaps in the sequence numbers)
  std::uint64_t saturated_frames = 0; // a force channel at its converter's end
  std::uint64_t fault_frames = 0;     // encoder or motor fault, watchdog stop
  double alignment_error_ms = 0.0;    // sensor frames against acceleration, after the time base
  std::string ended_because;          // empty while recording
};

struct RigSessionInfo {
  std::string tool, surface;
  double normal_load_N = 0.0;
  // WAV files store whole-number rates, so these must be whole numbers of hertz.
  double acceleration_rate_hz = 0.0;  // acceleration.wav (audio rate)
  double speed_rate_hz = 0.0;         // speed.wav
  double force_rate_hz = 0.0;         // normal_force.wav and tangential_force.wav
  // What each stream's numbers mean, e.g. {"acceleration": "audio full scale", "speed": "m/s"}.
  std::map<std::string, std::string> units;
  struct {
    // acceleration.wav holds the signal as captured; times this factor it is m/s².
    double accelerometer_m_s2_per_unit = 1.0;
    double force_counts_per_N = 403.2;  // the OptoForce sensor's sensitivity
    double lever_factor = 1.0;
  } calibration;
  std::string speed_profile;  // e.g. "sweep 17-250 mm/s, 3 s period"
  // What the motor was asked to do, as breakpoints joined by straight lines (a step: two points at
  // one time); empty when unknown. Key "speed_profile_points": {"time_s": [...], "speed_mm_s": [...]}.
  // Holds of one speed let a measurement analyse a capture step by step as the paper did.
  std::vector<double> profile_time_s, profile_speed_m_s;
  std::string notes;
  std::string created_utc;  // ISO 8601; the writer fills it in when empty
  std::optional<CaptureRecord> capture;  // key "capture"; absent in sessions not from a capture
};

// The files inside a session folder.
inline constexpr const char* kSessionJson = "session.json";
inline constexpr const char* kAccelerationWav = "acceleration.wav";
inline constexpr const char* kSpeedWav = "speed.wav";
inline constexpr const char* kNormalForceWav = "normal_force.wav";
inline constexpr const char* kTangentialForceWav = "tangential_force.wav";

// Records one session. Every append goes straight to its WAV file and the WAV header is rewritten
// after each block, so the .partial folder is valid at every moment. Not thread-safe: one capture
// thread appends.
class RigSessionWriter {
 public:
  // Creates <folder>.partial with session.json and the four empty streams. Throws
  // std::invalid_argument for an unusable RigSessionInfo and std::runtime_error when <folder> or
  // <folder>.partial already exists or cannot be created.
  RigSessionWriter(std::filesystem::path folder, RigSessionInfo info);
  ~RigSessionWriter();  // without finish(): closes the streams and leaves <folder>.partial readable
  RigSessionWriter(const RigSessionWriter&) = delete;
  RigSessionWriter& operator=(const RigSessionWriter&) = delete;

  // Each throws std::invalid_argument for a non-finite sample (nothing of the block is written),
  // std::runtime_error on a write failure and std::logic_error after finish().
  void append_acceleration(std::span<const float> samples);
  void append_speed(std::span<const float> samples_m_s);
  void append_normal_force(std::span<const float> samples_N);
  void append_tangential_force(std::span<const float> samples_N);

  // Rewrites session.json (atomically) with `record` as its "capture": how the capture is going.
  // Throws std::runtime_error on a write failure and std::logic_error after finish().
  void update_capture(const CaptureRecord& record);

  // Closes the streams, records the frame counts in session.json and renames <folder>.partial to
  // <folder> atomically; fails (std::runtime_error) without replacing anything if <folder> exists.
  void finish();
  // Closes the streams and removes <folder>.partial: for a capture refused before it recorded
  // anything, which leaves nothing behind. Nothing to do after finish().
  void discard() noexcept;

  const std::filesystem::path& partial_folder() const { return partial_; }
  const std::filesystem::path& folder() const { return folder_; }

 private:
  struct Stream;
  void append(Stream& stream, std::span<const float> samples);
  void close_streams() noexcept;

  std::filesystem::path folder_;
  std::filesystem::path partial_;
  RigSessionInfo info_;
  std::vector<std::unique_ptr<Stream>> streams_;  // acceleration, speed, normal, tangential
  bool finished_ = false;
};

struct RigSession {
  RigSessionInfo info;
  std::vector<float> acceleration, speed_m_s, normal_force_N, tangential_force_N;
  bool complete = false;  // false for a <folder>.partial left by an interrupted capture
  std::filesystem::path folder;
  // What the reader had to accept in a .partial folder (a stream whose data outlasts its header).
  std::vector<std::string> warnings;
};

// Reads a finished session folder, or a .partial folder up to its last fully written block.
// Throws FormatError for a missing or invalid session.json (naming the field), a WAV file that is
// not mono float32, has the wrong sample rate, holds NaN or infinite samples, or (finished
// sessions) holds a different number of frames than session.json records.
RigSession read_rig_session(const std::filesystem::path& folder);

// The path of the .partial folder a writer uses for `folder`.
std::filesystem::path partial_folder_of(const std::filesystem::path& folder);

}  // namespace nibrig::model::io
