#include "rig/replay_rig.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "model/io/paper_friction.hpp"
#include "model/io/paper_vibration.hpp"
#include "model/io/rig_session.hpp"
#include "model/measure/step_segmentation.hpp"
#include "rt/reference_load.hpp"

namespace nibrig::rig {
namespace {

struct Recording {
  RigDescription description;
  std::vector<SensorFrame> frames;
  std::vector<float> acceleration;
  std::vector<ProfilePoint> profile;
  std::string profile_description;
};

Recording from_session(const std::filesystem::path& folder) {
  const model::io::RigSession session = model::io::read_rig_session(folder);
  const auto& info = session.info;
  if (session.speed_m_s.empty() || session.acceleration.empty())
    throw std::invalid_argument(folder.string() +
                                ": the session holds no speed or no acceleration to replay");
  Recording r;
  RigDescription& d = r.description;
  d.tool = info.tool;
  d.surface = info.surface;
  d.frame_rate_hz = info.speed_rate_hz;
  d.acceleration_rate_hz = info.acceleration_rate_hz;
  d.normal_load_N = info.normal_load_N;
  d.accelerometer_m_s2_per_unit = info.calibration.accelerometer_m_s2_per_unit;
  d.force_counts_per_N = info.calibration.force_counts_per_N;
  d.lever_factor = info.calibration.lever_factor;
  if (const auto it = info.units.find("acceleration"); it != info.units.end())
    d.acceleration_units = it->second;
  // The forces may run at their own rate: each frame takes the force sample at or before it.
  const double force_per_frame = info.force_rate_hz / info.speed_rate_hz;
  const std::size_t frames = session.speed_m_s.size();
  r.frames.resize(frames);
  for (std::size_t k = 0; k < frames; ++k) {
    SensorFrame& f = r.frames[k];
    f.sequence = static_cast<std::uint32_t>(k);
    f.device_time_us = static_cast<std::uint64_t>(std::llround(1e6 * k / info.speed_rate_hz));
    f.speed_m_s = session.speed_m_s[k];
    const auto j = static_cast<std::size_t>(std::floor(static_cast<double>(k) * force_per_frame));
    if (j < session.normal_force_N.size()) f.normal_force_N = session.normal_force_N[j];
    if (j < session.tangential_force_N.size()) f.tangential_force_N = session.tangential_force_N[j];
  }
  r.acceleration = session.acceleration;
  if (!info.profile_time_s.empty()) {
    for (std::size_t i = 0; i < info.profile_time_s.size(); ++i)
      r.profile.push_back({info.profile_time_s[i], info.profile_speed_m_s[i]});
    r.profile_description = info.speed_profile;
  } else {  // no stored profile: the measured speed, every 10 ms
    for (std::size_t k = 0; k < frames; k += std::max<std::size_t>(1, frames / 10000))
      r.profile.push_back({k / info.speed_rate_hz, std::max(0.0f, session.speed_m_s[k])});
    r.profile_description = "the speed measured in " + folder.filename().string();
  }
  d.name = "replay of session " + folder.string() + " (" + info.tool + " on " + info.surface + ")";
  return r;
}

// A paper recording stores no speed: the speed is the step grid found in the signal (the same
// segmentation the catalog was built with), at rest outside the kept blocks.
Recording from_paper_recording(const std::filesystem::path& file) {
  const model::io::VibrationRecording recording = model::io::read_paper_vibration(file);
  const model::measure::StepProtocol protocol;
  const auto segmentation = model::measure::segment_speed_steps(recording.acceleration_m_s2,
                                                                recording.sample_rate_hz, protocol);
  Recording r;
  RigDescription& d = r.description;
  d.tool = recording.name.tool;
  d.surface = recording.name.surface;
  d.frame_rate_hz = recording.sample_rate_hz;
  d.acceleration_rate_hz = recording.sample_rate_hz;
  d.normal_load_N = rt::kReferenceNormalForce;  // the paper's protocol
  d.accelerometer_m_s2_per_unit = 1.0;
  d.acceleration_units = "m/s²";
  d.name = "replay of paper recording " + file.filename().string() + " (" + d.tool + " on " +
           d.surface + ")";
  const std::size_t n = recording.acceleration_m_s2.size();
  r.acceleration.assign(recording.acceleration_m_s2.begin(), recording.acceleration_m_s2.end());
  // Each kept block: from the window's start less its offset, one block long.
  const auto offset = static_cast<std::size_t>(std::llround(protocol.window_offset_s * d.frame_rate_hz));
  const auto block = static_cast<std::size_t>(std::llround(protocol.block_s * d.frame_rate_hz));
  std::vector<float> speed(n, 0.0f);
  r.profile.push_back({0.0, 0.0});
  for (const auto& step : segmentation.steps) {
    const std::size_t begin = step.begin >= offset ? step.begin - offset : 0;
    std::fill(speed.begin() + static_cast<std::ptrdiff_t>(std::min(n, begin)),
              speed.begin() + static_cast<std::ptrdiff_t>(std::min(n, begin + block)),
              static_cast<float>(step.speed_m_s));
    // The hold in the profile: its window then starts exactly where the segmentation put it
    // (steps_from_profile), so the replay is measured on the catalog's own windows.
    const double t0 = std::max(static_cast<double>(begin) / d.frame_rate_hz, r.profile.back().time_s);
    const double t1 = static_cast<double>(begin + block) / d.frame_rate_hz;
    if (t0 > r.profile.back().time_s) r.profile.push_back({t0, 0.0});
    if (r.profile.size() >= 2 && r.profile[r.profile.size() - 2].time_s == t0)
      r.profile.back().speed_m_s = step.speed_m_s;  // back to back: the rest point becomes the step
    else
      r.profile.push_back({t0, step.speed_m_s});
    r.profile.push_back({t1, step.speed_m_s});
    r.profile.push_back({t1, 0.0});
  }
  const double length = static_cast<double>(n) / d.frame_rate_hz;
  if (length > r.profile.back().time_s) r.profile.push_back({length, 0.0});
  r.profile_description = "the paper's steps as segmented from " + file.filename().string();
  r.frames.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    SensorFrame& f = r.frames[k];
    f.sequence = static_cast<std::uint32_t>(k);
    f.device_time_us = static_cast<std::uint64_t>(std::llround(recording.time_s[k] * 1e6));
    f.speed_m_s = speed[k];
    f.normal_force_N = static_cast<float>(d.normal_load_N);
  }
  return r;
}

// The friction run's forces on the frames, sample by sample at the frames' times; the tool rests
// (no drag) once the run has ended.
void play_friction_beside(Recording& r, const std::filesystem::path& file) {
  const model::io::FrictionRecording friction = model::io::read_paper_friction(file);
  RigDescription& d = r.description;
  if (friction.name.surface != d.surface)
    throw std::invalid_argument(file.string() + ": a friction recording on '" +
                                friction.name.surface + "' beside a vibration recording on '" +
                                d.surface + "'");
  d.normal_load_N = friction.name.normal_load_N;
  for (std::size_t k = 0; k < r.frames.size(); ++k) {
    const auto j = static_cast<std::size_t>(
        std::floor(static_cast<double>(k) * friction.sample_rate_hz / d.frame_rate_hz));
    SensorFrame& f = r.frames[k];
    f.normal_force_N = static_cast<float>(d.normal_load_N);
    f.tangential_force_N = j < friction.tangential_force_N.size()
                               ? static_cast<float>(friction.tangential_force_N[j])
                               : 0.0f;
  }
  d.name += " with the forces of " + file.filename().string();
}

}  // namespace

ReplayRig::ReplayRig(const std::filesystem::path& source, double speedup,
                     const std::filesystem::path& friction)
    : pacer_(speedup, 1.0) {
  if (!std::filesystem::exists(source))
    throw std::invalid_argument(source.string() + ": no such session or recording to replay");
  const bool session = std::filesystem::is_directory(source);
  if (session && !friction.empty())
    throw std::invalid_argument(friction.string() +
                                ": a session replays its own forces, not a friction recording's");
  Recording r = session ? from_session(source) : from_paper_recording(source);
  if (!friction.empty()) play_friction_beside(r, friction);
  description_ = std::move(r.description);
  description_.kind = "replay";
  frames_ = std::move(r.frames);
  acceleration_ = std::move(r.acceleration);
  profile_.emplace(r.profile_description, std::move(r.profile));
  description_.max_speed_m_s = std::max(profile_->max_speed_m_s(), 1e-3);
  pacer_ = Pacer(speedup, description_.frame_rate_hz);
}

void ReplayRig::start(const SpeedProfile& profile) {
  if (started_) throw std::logic_error("replay rig: already started");
  started_ = true;
  // As many frames as the profile lasts, and no more than both streams hold.
  const double rate_ratio = description_.acceleration_rate_hz / description_.frame_rate_hz;
  const auto by_acceleration = static_cast<std::uint64_t>(
      std::floor(static_cast<double>(acceleration_.size()) / rate_ratio));
  const auto by_profile =
      static_cast<std::uint64_t>(std::llround(profile.duration_s() * description_.frame_rate_hz));
  frames_total_ = std::min<std::uint64_t>({frames_.size(), by_acceleration, by_profile});
  pacer_.start();
}

bool ReplayRig::read(RigData& into, std::chrono::milliseconds wait) {
  if (!started_) throw std::logic_error("replay rig: read() before start()");
  const auto finish = [&] {
    if (health_.ended_because.empty()) health_.ended_because = stopped_ ? "stopped" : "profile finished";
    return false;
  };
  if (stopped_ || frames_made_ >= frames_total_) return finish();
  const std::uint64_t block = std::max<std::uint64_t>(1, static_cast<std::uint64_t>(description_.frame_rate_hz / 100));
  const std::uint64_t due = pacer_.due(frames_made_, frames_total_, block, 10 * block, wait);
  if (due <= frames_made_) return true;
  const std::size_t before = into.frames.size();
  into.frames.insert(into.frames.end(), frames_.begin() + static_cast<std::ptrdiff_t>(frames_made_),
                     frames_.begin() + static_cast<std::ptrdiff_t>(due));
  const auto samples_end = static_cast<std::uint64_t>(std::floor(
      static_cast<double>(due) * description_.acceleration_rate_hz / description_.frame_rate_hz));
  into.acceleration.insert(into.acceleration.end(),
                           acceleration_.begin() + static_cast<std::ptrdiff_t>(samples_made_),
                           acceleration_.begin() + static_cast<std::ptrdiff_t>(samples_end));
  tell_listener(into.frames, before);
  health_.frames += due - frames_made_;
  health_.acceleration_samples += samples_end - samples_made_;
  frames_made_ = due;
  samples_made_ = samples_end;
  if (frames_made_ >= frames_total_) return finish();
  return true;
}

void ReplayRig::stop() {
  if (!stopped_ && started_ && frames_made_ < frames_total_ && health_.ended_because.empty())
    health_.ended_because = "stopped";
  stopped_ = true;
}

}  // namespace nibrig::rig
