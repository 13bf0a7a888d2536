#include "model/io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

#include "model/io/finite_output.hpp"
#include "model/io/interrupt_cleanup.hpp"
#include "model/io/job_files.hpp"

namespace nibrig::model::io {

namespace {

thread_local OutputSet* open_set = nullptr;

void discard(const std::filesystem::path& temporary) {
  ::unlink(temporary.c_str());
  untrack_temporary(temporary);
}

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& what, int error) {
  throw OutputFileError(file.string() + ": cannot " + what + " (" + std::strerror(error) + ")");
}

// Follows a chain of symbolic links to its last name, which need not exist (a dangling link names
// the file to create). Links under /proc (/dev/stdout -> /proc/self/fd/1) end in the process's own
// open files: `through_proc` is set, and the caller writes to the name itself.
std::filesystem::path follow_links(const std::filesystem::path& named, bool& through_proc) {
  std::filesystem::path path = named;
  for (int hops = 0; hops < 40; ++hops) {
    std::error_code ec;
    if (!std::filesystem::is_symlink(std::filesystem::symlink_status(path, ec))) return path;
    const std::filesystem::path next = std::filesystem::read_symlink(path, ec);
    if (ec) fail(named, "follow the link " + path.string(), ec.value());
    path = next.is_absolute() ? next : path.parent_path() / next;
    if (path.lexically_normal().string().rfind("/proc/", 0) == 0) through_proc = true;
  }
  fail(named, "follow its links", ELOOP);
}

void write_all(int fd, std::string_view content, const std::filesystem::path& file) {
  std::size_t written = 0;
  while (written < content.size()) {
    const ssize_t n = ::write(fd, content.data() + written, content.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail(file, "write", errno);
    }
    written += static_cast<std::size_t>(n);
  }
}

void write_stream(const std::filesystem::path& file, std::string_view content) {
  const int fd = ::open(file.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (fd < 0) fail(file, "open for writing", errno);
  try {
    write_all(fd, content, file);
  } catch (...) {
    ::close(fd);
    throw;
  }
  if (::close(fd) != 0) fail(file, "close", errno);
}

}  // namespace

OutputTarget output_target(const std::filesystem::path& named) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(named, ec);  // follows links, /proc's too
  bool through_proc = false;
  const fs::path end = follow_links(named, through_proc);
  if (!fs::exists(status)) {
    if (through_proc) return {named, true};
    return {end, false};
  }
  switch (status.type()) {
    case fs::file_type::regular:
      if (through_proc) return {named, true};  // our own stdout redirected to a file
      refuse_replacing_input(named, end);
      return {end, false};
    case fs::file_type::character:
    case fs::file_type::fifo:
      return {named, true};
    case fs::file_type::directory:
      throw OutputFileError(named.string() + ": is a folder; expected a file to write");
    default:
      throw OutputFileError(named.string() +
                               ": is a block device or a socket; expected a regular file, a "
                               "character device or a pipe to write");
  }
}

void refuse_companion_link(const std::filesystem::path& companion, const std::filesystem::path& named) {
  std::error_code ec;
  if (!std::filesystem::is_symlink(std::filesystem::symlink_status(companion, ec))) return;
  const auto points_to = std::filesystem::read_symlink(companion, ec);
  throw OutputFileError(companion.string() + ": is a link (to " + points_to.string() + "), where " +
                        named.string() + " puts a file of its own; nothing was written: remove "
                        "the link or name the output elsewhere");
}

std::filesystem::path temporary_beside(const OutputTarget& target) {
  static std::atomic<unsigned> counter{0};
  std::filesystem::path temporary = target.stream ? std::filesystem::temp_directory_path() /
                                                        target.path.filename()
                                                  : target.path;
  temporary += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  track_temporary(temporary);
  return temporary;
}

void commit_output(const std::filesystem::path& temporary, const OutputTarget& target) {
  if (!target.stream) {
    if (open_set != nullptr) {
      open_set->hold(temporary, target.path);
      return;
    }
    if (std::rename(temporary.c_str(), target.path.c_str()) != 0) {
      const int error = errno;
      discard(temporary);
      fail(target.path, "replace", error);
    }
    untrack_temporary(temporary);
    note_output(target.path);
    return;
  }
  const int in = ::open(temporary.c_str(), O_RDONLY | O_CLOEXEC);
  if (in < 0) {
    const int error = errno;
    discard(temporary);
    fail(temporary, "read back", error);
  }
  std::string content;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(in, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    content.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(in);
  discard(temporary);
  write_stream(target.path, content);
}

OutputSet::OutputSet() : outer_(open_set) { open_set = this; }

OutputSet::~OutputSet() {
  open_set = outer_;
  for (const auto& [temporary, target] : held_) discard(temporary);
}

void OutputSet::hold(const std::filesystem::path& temporary, const std::filesystem::path& target) {
  for (const auto& [other, held_target] : held_) {
    std::error_code ec;
    if (held_target == target || std::filesystem::equivalent(held_target, target, ec)) {
      discard(temporary);
      throw OutputFileError(target.string() + ": is written twice by one set of outputs; the " +
                            "names chosen make two of its files the same");
    }
  }
  held_.emplace_back(temporary, target);
}

void OutputSet::commit() {
  open_set = outer_;
  while (!held_.empty()) {
    const auto [temporary, target] = held_.front();
    held_.erase(held_.begin());
    if (std::rename(temporary.c_str(), target.c_str()) != 0) {
      const int error = errno;
      discard(temporary);
      fail(target, "replace", error);  // the destructor removes the rest
    }
    untrack_temporary(temporary);
    note_output(target);
  }
}

void write_file_atomically(const std::filesystem::path& named, std::string_view content) {
  if (named.extension() == ".csv") check_csv_finite(content, named);
  const OutputTarget target = output_target(named);
  if (target.stream) {
    write_stream(target.path, content);
    return;
  }
  const std::filesystem::path temporary = temporary_beside(target);
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) {
    const int error = errno;
    untrack_temporary(temporary);
    fail(temporary, "create", error);
  }
  try {
    write_all(fd, content, temporary);
  } catch (...) {
    ::close(fd);
    discard(temporary);
    throw;
  }
  // Flushed before the rename, or a crash could leave the new name pointing at empty data.
  if (::fsync(fd) != 0) {
    const int error = errno;
    ::close(fd);
    discard(temporary);
    fail(temporary, "flush to disk", error);
  }
  if (::close(fd) != 0) {
    const int error = errno;
    discard(temporary);
    fail(temporary, "close", error);
  }
  commit_output(temporary, target);
}

}  // namespace nibrig::model::io
