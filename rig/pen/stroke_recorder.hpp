// Recording what a pen draws into the paper's drawing-trajectory format (model/io's
// DrawingTrajectoryWriter), one new file per recording, so that a stroke drawn on a tablet replays
// with `render --trajectory` and wherever the artists' files play.
//
// Threads: start() and stop() on a control thread (a face's); add() and tablet_removed() on the
// pen reader's thread (PenEvents). The reader's thread also feeds the engine's live contact, so
// add() never waits for the disk: it queues the report under a lock held only to append it, and
// the recorder's own thread writes the queue out (a write per report, a flush to disk once a
// second, either of which a slow disk can hold up for long).
#pragma once

#include <condition_variable>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "model/io/drawing_trajectory_writer.hpp"
#include "rig/pen/pen_sample.hpp"

namespace nibrig::rig::pen {

struct StrokeRecorderSettings {
  std::filesystem::path folder;  // where the recordings go; made when missing
  std::string tool = "pen";      // the file name's tool and surface (drawing_file_name)
  std::string surface = "tablet";
  std::string pen;  // the subject: the pen's or tablet's name; a UTC stamp is added
};

struct RecordingSummary {
  std::filesystem::path file;
  std::uint64_t reports = 0;  // received while recording
  std::uint64_t rows = 0;     // written (reports of one millisecond share a row)
  std::string ended_because;  // "stopped", "the tablet was removed", or the write's error
  bool kept = true;           // false: fewer than 2 rows, which no reader accepts; removed
};

class StrokeRecorder {
 public:
  explicit StrokeRecorder(StrokeRecorderSettings settings);
  ~StrokeRecorder();  // stops a recording in progress
  StrokeRecorder(const StrokeRecorder&) = delete;
  StrokeRecorder& operator=(const StrokeRecorder&) = delete;

  // Control thread. Opens a new file, <tool>_<surface>_<pen>-<UTC time>.csv (with -2, -3 … when
  // that name is taken), and records from the next report on; returns its path. Throws what the
  // writer throws (a folder that cannot be written, naming it) and std::logic_error while
  // recording.
  std::filesystem::path start();
  // Control thread. Writes what is queued, closes the file and says how it went; nullopt when
  // nothing was recording (or the tablet's removal already ended it: see last()).
  std::optional<RecordingSummary> stop();
  bool recording() const;
  // The summary of the recording that ended last, however it ended.
  std::optional<RecordingSummary> last() const;

  // Pen reader's thread. One report and the force the contact has at it (N); ignored unless
  // recording. Never waits for the disk.
  void add(const PenSample& sample, double normal_force_N);
  // Pen reader's thread, from PenEvents::removed: the recording ends with everything received
  // written and the file closed before this returns.
  void tablet_removed();

 private:
  struct Queued {
    PenSample sample;
    double normal_force_N;
  };
  void write_loop();
  RecordingSummary finish(const std::string& why);

  StrokeRecorderSettings settings_;
  std::mutex control_;  // start, stop and tablet_removed, one at a time

  mutable std::mutex queue_mutex_;
  std::condition_variable queue_changed_;
  std::vector<Queued> queue_;
  bool recording_ = false;
  bool closing_ = false;
  std::uint64_t reports_ = 0;
  std::string write_error_;
  std::optional<RecordingSummary> last_;

  std::unique_ptr<model::io::DrawingTrajectoryWriter> writer_;  // the writer thread's alone
  std::thread writer_thread_;
};

}  // namespace nibrig::rig::pen
