// What the turntable is asked to do: a speed over time, as breakpoints joined by straight lines. A
// step is two breakpoints at the same instant; a sweep is a triangle; anything else comes from a
// file. The same profile drives the simulated rig, is uploaded to the USB controller
// (PROTOCOL.md) and is written into every session, so a capture says what was asked of the motor.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace nibrig::rig {

// A profile lasts at most a day: no capture is longer, and a longer one would fill memory and disk.
inline constexpr double kMaxProfileSeconds = 86400.0;
// fit_to_duration repeats a profile into at most this many breakpoints (a day of the paper's steps
// is about 90 000).
inline constexpr std::size_t kMaxProfilePoints = 1000000;

struct ProfilePoint {
  double time_s = 0.0;
  double speed_m_s = 0.0;
};

class SpeedProfile {
 public:
  // Throws std::invalid_argument naming the point when there is no point, the first time is not 0,
  // a time goes backwards or passes kMaxProfileSeconds, more than two points share a time, or a
  // value is not finite or a speed is negative.
  SpeedProfile(std::string description, std::vector<ProfilePoint> points);

  const std::string& description() const { return description_; }
  const std::vector<ProfilePoint>& points() const { return points_; }
  double duration_s() const { return points_.back().time_s; }
  double max_speed_m_s() const;
  // The target at time t: linear between breakpoints, the later value at a step, the last value
  // after the end and the first before 0.
  double speed_at(double t) const;

 private:
  std::string description_;
  std::vector<ProfilePoint> points_;
};

// Throws std::invalid_argument "the profile asks for X mm/s; the motor follows 0-Y mm/s" when the
// profile is faster than a motor whose top speed is `max_speed_m_s`: the one line every rig and
// the capture give for it.
void check_within_motor(const SpeedProfile& profile, double max_speed_m_s);

// The paper's measurement protocol (Sec. 3; model/measure/step_segmentation.hpp): per sweep 2 s at
// rest, then six 2 s steps rising over 17-250 mm/s, sweeps repeated back to back; `seconds` cuts or
// extends the whole (whole sweeps: 14 s each) and is rounded up to at least one sweep when zero.
SpeedProfile paper_steps(double seconds = 0.0);
// The user study's sweep (Sec. 8): 17 → 250 → 17 mm/s, linearly, a 3 s period, for `seconds`.
SpeedProfile study_sweep_profile(double seconds);
// A CSV file `time_s,speed_mm_s` (header line required, # comments allowed). Throws
// model::io::FormatError naming the file and line.
SpeedProfile read_speed_profile(const std::filesystem::path& file);

// The same profile stretched or cut to `seconds` (repeating it from the start when longer).
// Throws std::invalid_argument for `seconds` outside (0, kMaxProfileSeconds] or a repetition of
// more than kMaxProfilePoints breakpoints.
SpeedProfile fit_to_duration(const SpeedProfile& profile, double seconds);

}  // namespace nibrig::rig
