#include "model/io/drawing_trajectory_writer.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <numbers>
#include <stdexcept>

#include "model/io/finite_output.hpp"
#include "model/io/text_lines.hpp"

namespace nibrig::model::io {

namespace {

constexpr const char* kWrittenDrawingHeader =
    "Unix Timestamp,X,Y,Z,Phi,Theta,F,Ground,Touch,Speed,Acceeration\n";
constexpr long long kDrawingSyncEvery_ms = 1000;

bool drawing_name_char(char c, bool underscore_allowed) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' ||
         c == '.' || (underscore_allowed && c == '_');
}

std::string sanitised_name_part(const std::string& text, bool underscore_allowed,
                                const char* part) {
  std::string out;
  for (char c : text) {
    const char kept = drawing_name_char(c, underscore_allowed) ? c : '-';
    const bool separator = kept == '-' || kept == '_';
    if (separator && (out.empty() || out.back() == '-' || out.back() == '_')) continue;
    out.push_back(kept);
  }
  while (!out.empty() && (out.back() == '-' || out.back() == '_')) out.pop_back();
  if (out.empty() || out.find_first_not_of('.') == std::string::npos)
    throw std::invalid_argument(std::string("a drawing recording's ") + part + " '" + text +
                                "' has no letter or digit to name the file with");
  return out;
}

std::string system_reason(int error) { return std::strerror(error); }

// The pen's lean as the angle from the normal and its azimuth in the tablet's plane: the direction
// along the pen is (tan tilt_x, tan tilt_y, 1).
void pen_orientation_deg(const DrawingFrame& f, double& phi, double& theta) {
  constexpr double kDegree = std::numbers::pi / 180.0;
  const double ax = std::tan(f.tilt_x_deg * kDegree);
  const double ay = std::tan(f.tilt_y_deg * kDegree);
  phi = std::atan(std::hypot(ax, ay)) / kDegree;
  theta = (ax == 0.0 && ay == 0.0) ? 0.0 : std::atan2(ay, ax) / kDegree;
}

}  // namespace

WallClockOrigin WallClockOrigin::now() {
  timespec wall{}, mono{};
  ::clock_gettime(CLOCK_MONOTONIC, &mono);
  ::clock_gettime(CLOCK_REALTIME, &wall);
  WallClockOrigin origin;
  origin.unix_ms = static_cast<long long>(wall.tv_sec) * 1000 + wall.tv_nsec / 1000000;
  // The monotonic instant of that whole millisecond, so that a report read now stamps as now.
  origin.monotonic_s = static_cast<double>(mono.tv_sec) + static_cast<double>(mono.tv_nsec) * 1e-9 -
                       static_cast<double>(wall.tv_nsec % 1000000) * 1e-9;
  return origin;
}

std::string drawing_file_name(const std::string& tool, const std::string& surface,
                              const std::string& subject) {
  return sanitised_name_part(tool, false, "tool") + "_" +
         sanitised_name_part(surface, false, "surface") + "_" +
         sanitised_name_part(subject, true, "subject") + ".csv";
}

DrawingTrajectoryWriter::DrawingTrajectoryWriter(std::filesystem::path file, WallClockOrigin origin)
    : file_(std::move(file)), origin_(origin) {
  const std::string name = file_.filename().string();
  const auto stem = csv_stem(file_);
  bool splits = stem && !name.ends_with(".gz");
  if (splits) {
    const auto tokens = split_fields(*stem, '_');
    splits = tokens.size() >= 3;
    for (auto token : tokens) splits = splits && !token.empty();
  }
  if (!splits)
    throw std::invalid_argument(file_.string() +
                                ": a drawing recording is named <tool>_<surface>_<subject>.csv "
                                "(plain text, no empty part), found '" +
                                name + "'");
  std::error_code ec;
  if (std::filesystem::is_directory(file_, ec))
    throw std::runtime_error(file_.string() + ": is a folder, expected a new file to record into");
  if (std::filesystem::exists(std::filesystem::symlink_status(file_, ec)))
    throw std::runtime_error(file_.string() +
                             ": exists already; a recording never replaces a file");
  const std::filesystem::path folder = file_.parent_path();
  if (!folder.empty() && !std::filesystem::is_directory(folder, ec)) {
    std::filesystem::create_directories(folder, ec);
    if (ec)
      throw std::runtime_error(folder.string() + ": cannot create the folder to record into (" +
                               ec.message() + ")");
  }
  fd_ = ::open(file_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    const int error = errno;
    if (error == EEXIST)
      throw std::runtime_error(file_.string() +
                               ": exists already; a recording never replaces a file");
    throw std::runtime_error((folder.empty() ? std::filesystem::path(".") : folder).string() +
                             ": cannot create " + name + " in this folder (" +
                             system_reason(error) + ")");
  }
  try {
    write_all(kWrittenDrawingHeader);
    sync();
  } catch (...) {
    ::close(fd_);
    fd_ = -1;
    throw;
  }
}

DrawingTrajectoryWriter::~DrawingTrajectoryWriter() {
  try {
    close();
  } catch (const std::exception&) {
    // The rows already written stay in the file; a destructor has no one to tell.
  }
}

void DrawingTrajectoryWriter::append(const DrawingFrame& frame) {
  if (fd_ < 0) throw std::logic_error(file_.string() + ": appended to after close()");
  const std::uint64_t row_number = rows_written_ + (has_open_row_ ? 1 : 0) + 1;
  const struct {
    const char* name;
    double value;
  } fields[] = {{"Unix Timestamp", frame.time_s},
                {"X", frame.x_m},
                {"Y", frame.y_m},
                {"Z", frame.z_m},
                {"Phi", frame.tilt_x_deg},
                {"Theta", frame.tilt_y_deg},
                {"F", frame.normal_force_N}};
  for (const auto& field : fields) {
    if (!std::isfinite(field.value))
      throw UnwritableOutput("not writing " + file_.string() + ": row " +
                             std::to_string(row_number) + ", field '" + field.name +
                             "' is not a finite number");
  }
  Row row;
  row.unix_ms = origin_.unix_ms + std::llround((frame.time_s - origin_.monotonic_s) * 1000.0);
  row.frame = frame;
  if (has_open_row_) {
    if (row.unix_ms == open_row_.unix_ms) {
      open_row_ = row;
      ++merged_;
      return;
    }
    if (row.unix_ms < open_row_.unix_ms)
      throw std::invalid_argument(file_.string() + ": a pen report at " +
                                  std::to_string(row.unix_ms) + " ms came after one at " +
                                  std::to_string(open_row_.unix_ms) +
                                  " ms; reports must arrive in time order");
    write_row(open_row_);
  }
  open_row_ = row;
  has_open_row_ = true;
}

void DrawingTrajectoryWriter::write_row(const Row& row) {
  const DrawingFrame& f = row.frame;
  double speed_mm = 0.0, acceleration_mm = 0.0;
  if (has_previous_) {
    speed_mm = std::hypot(f.x_m - previous_.frame.x_m, f.y_m - previous_.frame.y_m) * 1e3;
    acceleration_mm = speed_mm - previous_speed_mm_;
  } else {
    last_sync_ms_ = row.unix_ms;
  }
  double phi = 0.0, theta = 0.0;
  pen_orientation_deg(f, phi, theta);
  char text[320];
  const int length =
      std::snprintf(text, sizeof text, "%lld,%.4f,%.4f,%.4f,%.2f,%.2f,%.4f,0,%d,%.6f,%.6f\n",
                    row.unix_ms, f.x_m * 1e3, f.y_m * 1e3, f.z_m * 1e3, phi, theta,
                    f.normal_force_N, f.touching ? 1 : 0, speed_mm, acceleration_mm);
  if (length <= 0 || static_cast<std::size_t>(length) >= sizeof text)
    throw UnwritableOutput("not writing " + file_.string() + ": row " +
                           std::to_string(rows_written_ + 1) + " is longer than a row can be");
  write_all(std::string(text, static_cast<std::size_t>(length)));
  previous_ = row;
  previous_speed_mm_ = speed_mm;
  has_previous_ = true;
  ++rows_written_;
  if (row.unix_ms - last_sync_ms_ >= kDrawingSyncEvery_ms) {
    sync();
    last_sync_ms_ = row.unix_ms;
  }
}

void DrawingTrajectoryWriter::write_all(const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd_, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int error = n < 0 ? errno : EIO;
      // A full disk can take half a row: cut it off again, or the reader would take a number cut
      // short in the Speed column for a whole one.
      const bool whole = done == 0 || (::ftruncate(fd_, bytes_written_) == 0 &&
                                       ::lseek(fd_, bytes_written_, SEEK_SET) == bytes_written_);
      throw std::runtime_error(file_.string() + ": cannot write the recording (" +
                               system_reason(error) + ")" +
                               (whole ? "" : "; its last line is cut short"));
    }
    done += static_cast<std::size_t>(n);
  }
  bytes_written_ += static_cast<long long>(text.size());
}

void DrawingTrajectoryWriter::sync() {
  if (::fdatasync(fd_) != 0 && errno != EINVAL)  // EINVAL: a pipe or device, nothing to flush
    throw std::runtime_error(file_.string() + ": cannot flush the recording to disk (" +
                             system_reason(errno) + ")");
}

void DrawingTrajectoryWriter::close() {
  if (fd_ < 0) return;
  try {
    if (has_open_row_) {
      has_open_row_ = false;
      write_row(open_row_);
    }
    sync();
  } catch (...) {
    ::close(fd_);
    fd_ = -1;
    throw;
  }
  const int result = ::close(fd_);
  fd_ = -1;
  if (result != 0)
    throw std::runtime_error(file_.string() + ": cannot close the recording (" +
                             system_reason(errno) + ")");
}

}  // namespace nibrig::model::io
