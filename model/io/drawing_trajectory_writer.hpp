// Writing a pen stroke in the paper's drawing-trajectory format (paper_drawing.hpp), one row per
// pen report as it arrives, so that what a pen draws replays wherever the artists' files do. Each
// row goes to the file in one write as soon as its millisecond is over: a process killed mid-stroke
// leaves a file the reader reads, short of the row still open.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace nibrig::model::io {

// The format's clock is Unix time in ms; a pen reports on CLOCK_MONOTONIC. The origin ties the two:
// the same instant read on both clocks.
struct WallClockOrigin {
  long long unix_ms = 0;
  double monotonic_s = 0.0;
  // Both clocks read now, back to back.
  static WallClockOrigin now();
};

// One pen report in SI units on the monotonic clock.
struct DrawingFrame {
  double time_s = 0.0;  // CLOCK_MONOTONIC
  double x_m = 0.0, y_m = 0.0;
  double z_m = 0.0;  // height above the tablet when known; the paper's tracker wrote its own
  // The pen's lean from the normal in the x-z and y-z planes, as libinput gives it.
  double tilt_x_deg = 0.0, tilt_y_deg = 0.0;
  double normal_force_N = 0.0;
  bool touching = false;
};

// "<tool>_<surface>_<subject>.csv", the name read_paper_drawing splits back into the three. Tool
// and surface keep letters, digits, '-' and '.'; the subject may also hold '_' (the paper's
// "bottle_c2"); anything else (a space, '/', a byte beyond ASCII) becomes '-', runs of separators
// are one, and none leads or ends a part. Throws std::invalid_argument naming the part that is
// left empty.
std::string drawing_file_name(const std::string& tool, const std::string& surface,
                              const std::string& subject);

// Columns as the authors wrote them: Unix Timestamp (ms), X, Y, Z (mm), Phi (the pen's angle from
// the tablet's normal) and Theta (the azimuth of its lean, from +X toward +Y) in degrees, F (N),
// Ground (0: the tracker's own value, undocumented upstream), Touch (0/1), Speed (the in-plane
// distance to the previous row, mm/frame) and Acceeration (sic; this row's Speed minus the last
// one's, mm/frame², as the authors' files have it). The first row's Speed and Acceeration are 0.
// Positions are written to 0.0001 mm and forces to 0.0001 N.
//
// Reports that round to the millisecond of the row still open replace it (the format's stamps must
// increase, and libinput sends a tip change and the axes at one instant as separate events): that
// row is written when a later millisecond arrives or on close(). The file's data reaches the disk
// (fdatasync) once a second of recording and on close(). A write that fails part-way (a full disk)
// takes its part back, so the file only ever holds whole lines. Not thread-safe: one thread
// appends.
class DrawingTrajectoryWriter {
 public:
  // Creates `file` with the header line, and its folder when missing. Throws std::invalid_argument
  // for a name the reader would not split (drawing_file_name makes one that it does), and
  // std::runtime_error naming the file or folder when it exists already (a recording never
  // replaces one), is a folder, or cannot be created or written, with the system's reason.
  DrawingTrajectoryWriter(std::filesystem::path file, WallClockOrigin origin);
  ~DrawingTrajectoryWriter();  // close(), errors swallowed: the rows written stay readable
  DrawingTrajectoryWriter(const DrawingTrajectoryWriter&) = delete;
  DrawingTrajectoryWriter& operator=(const DrawingTrajectoryWriter&) = delete;

  // Throws UnwritableOutput (finite_output.hpp) naming the file, the row and the field for a value
  // that is not finite, std::invalid_argument for a report earlier than the last one, and
  // std::runtime_error on a write failure; std::logic_error after close().
  void append(const DrawingFrame& frame);

  // Writes the open row, flushes to disk and closes. Idempotent.
  void close();

  const std::filesystem::path& file() const { return file_; }
  std::uint64_t rows_written() const { return rows_written_; }
  // Reports folded into a row of the same millisecond.
  std::uint64_t merged_reports() const { return merged_; }

 private:
  struct Row {
    long long unix_ms = 0;
    DrawingFrame frame;
  };
  void write_row(const Row& row);
  void write_all(const std::string& text);
  void sync();

  std::filesystem::path file_;
  WallClockOrigin origin_;
  int fd_ = -1;
  bool has_open_row_ = false;
  Row open_row_;
  bool has_previous_ = false;
  Row previous_;                    // the last row written
  double previous_speed_mm_ = 0.0;  // its Speed column
  long long last_sync_ms_ = 0;
  long long bytes_written_ = 0;  // whole lines only
  std::uint64_t rows_written_ = 0;
  std::uint64_t merged_ = 0;
};

}  // namespace nibrig::model::io
