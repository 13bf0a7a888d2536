#include "rig/capture.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "model/io/rig_session.hpp"

namespace nibrig::rig {
namespace {

// The slow streams of a batch, with frames lost on the way (sequence gaps) filled by holding the
// last value, so that every stream keeps its constant rate and its timeline.
struct SlowStreams {
  std::vector<float> speed, normal, tangential;
  bool have_last = false;
  std::uint32_t last_sequence = 0;
  SensorFrame last;
  std::uint64_t filled = 0;

  void take(const std::vector<SensorFrame>& frames) {
    speed.clear(), normal.clear(), tangential.clear();
    for (const SensorFrame& f : frames) {
      if (have_last) {
        const std::uint32_t gap = f.sequence - last_sequence - 1;  // wraps like the counter
        // A frame older than the last (reordered, duplicated) is not written twice; a gap is
        // filled with at most 100 000 frames (100 s at 1 kHz): a longer one is the device's
        // counter starting again, not a loss to fill.
        if (gap >= 0x80000000u) continue;
        for (std::uint32_t g = 0; g < gap && g < 100000; ++g) push(last), ++filled;
      }
      push(f);
      last = f, last_sequence = f.sequence, have_last = true;
    }
  }
  void push(const SensorFrame& f) {
    speed.push_back(f.speed_m_s);
    normal.push_back(f.normal_force_N);
    tangential.push_back(f.tangential_force_N);
  }
};

// A capture makes its folder: anything already at that path is refused, saying what it is, since
// "a session already exists there" misleads for an empty folder, a file or a device. Thrown as
// std::runtime_error, as the writer's own refusal.
void check_capture_folder_free(const std::filesystem::path& folder) {
  std::error_code ec;
  const auto status = std::filesystem::status(folder, ec);
  if (!std::filesystem::exists(status)) return;
  const std::string at = folder.string() + ": ";
  const std::string why = "; a capture writes a new session folder: name one that does not exist";
  if (std::filesystem::is_directory(status)) {
    if (std::filesystem::exists(folder / model::io::kSessionJson, ec))
      throw std::runtime_error(at + "a session already exists there" + why);
    const bool empty = std::filesystem::is_empty(folder, ec);
    throw std::runtime_error(at + (empty ? "an empty folder" : "a folder that holds no session") + " is there" + why);
  }
  if (std::filesystem::is_regular_file(status)) throw std::runtime_error(at + "is a file, not a folder" + why);
  throw std::runtime_error(at + "is a device or special file, not a folder" + why);
}

}  // namespace

model::io::RigSessionInfo session_info_for(const RigDescription& rig, const SpeedProfile& profile,
                                        const CaptureOptions& options) {
  model::io::RigSessionInfo info;
  info.tool = options.tool.empty() ? rig.tool : options.tool;
  info.surface = options.surface.empty() ? rig.surface : options.surface;
  if (info.tool.empty() || info.surface.empty())
    throw std::invalid_argument("say which tool and surface are mounted (--tool, --surface): the " +
                                rig.kind + " rig cannot know");
  info.normal_load_N = rig.normal_load_N;
  info.acceleration_rate_hz = rig.acceleration_rate_hz;
  info.speed_rate_hz = rig.frame_rate_hz;
  info.force_rate_hz = rig.frame_rate_hz;
  info.units = {{"acceleration", rig.acceleration_units},
                {"speed", "m/s (encoder)"},
                {"normal_force", "N"},
                {"tangential_force", "N"}};
  info.calibration.accelerometer_m_s2_per_unit = rig.accelerometer_m_s2_per_unit;
  info.calibration.force_counts_per_N = rig.force_counts_per_N;
  info.calibration.lever_factor = rig.lever_factor;
  info.speed_profile = profile.description();
  for (const ProfilePoint& p : profile.points()) {
    info.profile_time_s.push_back(p.time_s);
    info.profile_speed_m_s.push_back(p.speed_m_s);
  }
  info.notes = options.notes;
  info.capture = model::io::CaptureRecord{};
  info.capture->rig = rig.name;
  return info;
}

CaptureResult capture_session(Rig& rig, const SpeedProfile& profile, const CaptureOptions& options) {
  const RigDescription& d = rig.description();
  check_within_motor(profile, d.max_speed_m_s);  // before any folder exists
  check_capture_folder_free(options.folder);
  model::io::RigSessionWriter writer(options.folder, session_info_for(d, profile, options));
  model::io::CaptureRecord record = model::io::CaptureRecord{};
  record.rig = d.name;
  try {
    rig.start(profile);
  } catch (...) {
    writer.discard();  // refused before anything was recorded: nothing is left behind
    throw;
  }

  RigData data;
  SlowStreams slow;
  bool more = true, cancelled = false;
  auto last_record = std::chrono::steady_clock::now();
  std::uint64_t samples = 0;
  const auto update_record = [&] {
    const RigHealth h = rig.health();
    record.seconds = static_cast<double>(samples) / d.acceleration_rate_hz;
    record.frames = h.frames;
    // The rig counts its losses; the gaps filled here are the same losses seen in the frames.
    record.dropped_frames = std::max(h.dropped_frames, slow.filled);
    record.saturated_frames = h.saturated_frames;
    record.fault_frames = h.fault_frames;
    record.alignment_error_ms = h.alignment_error_ms;
  };
  try {
    while (more) {
      if (!cancelled && options.cancel.stop_requested()) {
        cancelled = true;
        rig.stop();
      }
      data.clear();
      more = rig.read(data, std::chrono::milliseconds(100));
      slow.take(data.frames);
      writer.append_speed(slow.speed);
      writer.append_normal_force(slow.normal);
      writer.append_tangential_force(slow.tangential);
      writer.append_acceleration(data.acceleration);
      samples += data.acceleration.size();
      if (options.on_data) options.on_data(data);
      const auto now = std::chrono::steady_clock::now();
      if (now - last_record >= std::chrono::duration<double>(options.record_every_s)) {
        last_record = now;
        update_record();
        writer.update_capture(record);
        if (options.on_progress) {
          CaptureProgress p;
          p.seconds = record.seconds;
          p.duration_s = profile.duration_s();
          p.speed_m_s = slow.have_last ? slow.last.speed_m_s : 0.0;
          p.dropped_frames = record.dropped_frames;
          options.on_progress(p);
        }
      }
    }
  } catch (...) {
    // Whatever went wrong, what was recorded stays: the record says why it ended, the folder
    // stays .partial (readable) and the rig's motor is stopped. Nothing recorded: nothing stays.
    rig.stop();
    if (samples == 0) {
      writer.discard();
      throw;
    }
    update_record();
    record.ended_because = "capture failed";
    try {
      writer.update_capture(record);
    } catch (...) {
    }
    throw;
  }
  update_record();
  const RigHealth h = rig.health();
  record.ended_because = cancelled ? "interrupted" : h.ended_because;
  writer.update_capture(record);
  CaptureResult result;
  result.complete = !cancelled && h.ended_because == "profile finished";
  result.record = record;
  writer.finish();
  result.folder = writer.folder();
  return result;
}

}  // namespace nibrig::rig
