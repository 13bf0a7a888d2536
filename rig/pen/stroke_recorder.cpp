#include "rig/pen/stroke_recorder.hpp"

#include <stdexcept>

#include "model/io/utc_time.hpp"

namespace nibrig::rig::pen {

namespace {

model::io::DrawingFrame recorded_frame(const PenSample& s, double normal_force_N) {
  model::io::DrawingFrame f;
  f.time_s = s.time_s;
  f.x_m = s.x_m;
  f.y_m = s.y_m;
  f.tilt_x_deg = s.tilt_x_deg;
  f.tilt_y_deg = s.tilt_y_deg;
  f.normal_force_N = normal_force_N;
  f.touching = s.tip_down;
  return f;
}

}  // namespace

StrokeRecorder::StrokeRecorder(StrokeRecorderSettings settings) : settings_(std::move(settings)) {}

StrokeRecorder::~StrokeRecorder() {
  std::lock_guard control(control_);
  if (writer_) finish("stopped");
}

std::filesystem::path StrokeRecorder::start() {
  std::lock_guard control(control_);
  if (writer_)
    throw std::logic_error("a stroke recording is already running into " +
                           writer_->file().string());
  const std::string subject = (settings_.pen.empty() ? std::string("pen") : settings_.pen) + "-" +
                              model::io::now_utc_iso8601();
  const std::string stem = model::io::drawing_file_name(settings_.tool, settings_.surface, subject);
  std::filesystem::path file = settings_.folder / stem;
  for (int n = 2; std::filesystem::exists(std::filesystem::symlink_status(file)); ++n)
    file = settings_.folder / (stem.substr(0, stem.size() - 4) + "-" + std::to_string(n) + ".csv");
  writer_ =
      std::make_unique<model::io::DrawingTrajectoryWriter>(file, model::io::WallClockOrigin::now());
  {
    std::lock_guard lock(queue_mutex_);
    queue_.clear();
    recording_ = true;
    closing_ = false;
    reports_ = 0;
    write_error_.clear();
  }
  writer_thread_ = std::thread([this] { write_loop(); });
  return file;
}

std::optional<RecordingSummary> StrokeRecorder::stop() {
  std::lock_guard control(control_);
  if (!writer_) return std::nullopt;
  return finish("stopped");
}

void StrokeRecorder::tablet_removed() {
  std::lock_guard control(control_);
  if (writer_) finish("the tablet was removed");
}

bool StrokeRecorder::recording() const {
  std::lock_guard lock(queue_mutex_);
  return recording_;
}

std::optional<RecordingSummary> StrokeRecorder::last() const {
  std::lock_guard lock(queue_mutex_);
  return last_;
}

void StrokeRecorder::add(const PenSample& sample, double normal_force_N) {
  {
    std::lock_guard lock(queue_mutex_);
    if (!recording_) return;
    queue_.push_back({sample, normal_force_N});
    ++reports_;
  }
  queue_changed_.notify_one();
}

void StrokeRecorder::write_loop() {
  std::vector<Queued> batch;
  bool failed = false;
  for (;;) {
    bool last_round = false;
    {
      std::unique_lock lock(queue_mutex_);
      queue_changed_.wait(lock, [this] { return !queue_.empty() || closing_; });
      batch.swap(queue_);
      last_round = closing_;
    }
    for (const Queued& q : batch) {
      if (failed) break;
      try {
        writer_->append(recorded_frame(q.sample, q.normal_force_N));
      } catch (const std::exception& error) {
        // A full disk or a bad report: the recording ends here, and stop() says why.
        failed = true;
        std::lock_guard lock(queue_mutex_);
        write_error_ = error.what();
        recording_ = false;
      }
    }
    batch.clear();
    if (last_round) return;
  }
}

RecordingSummary StrokeRecorder::finish(const std::string& why) {
  {
    std::lock_guard lock(queue_mutex_);
    recording_ = false;  // add() queues nothing more; what it queued is written below
    closing_ = true;
  }
  queue_changed_.notify_one();
  writer_thread_.join();
  RecordingSummary summary;
  summary.file = writer_->file();
  std::string error;
  try {
    writer_->close();
  } catch (const std::exception& e) {
    error = e.what();
  }
  summary.rows = writer_->rows_written();
  writer_.reset();
  {
    std::lock_guard lock(queue_mutex_);
    summary.reports = reports_;
    if (error.empty()) error = write_error_;
  }
  summary.ended_because = error.empty() ? why : error;
  if (summary.rows < 2) {
    std::error_code ignored;
    std::filesystem::remove(summary.file, ignored);
    summary.kept = false;
  }
  std::lock_guard lock(queue_mutex_);
  last_ = summary;
  return summary;
}

}  // namespace nibrig::rig::pen
