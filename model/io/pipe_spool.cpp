#include "model/io/pipe_spool.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <map>
#include <mutex>
#include <string>

#include "model/io/bounded_read.hpp"
#include "model/io/format_error.hpp"
#include "model/io/interrupt_cleanup.hpp"

namespace nibrig::model::io {
namespace {

struct Spools {
  std::mutex mutex;
  std::map<std::string, std::filesystem::path> copies;  // by the name the pipe was given as
  ~Spools() {
    for (const auto& [name, copy] : copies) {
      ::unlink(copy.c_str());
      untrack_temporary(copy);
    }
  }
};

Spools& spools() {
  static Spools instance;
  return instance;
}

[[noreturn]] void pipe_failure(const std::filesystem::path& file, const std::string& what, int error) {
  throw FormatError(file, "", what + " (" + std::strerror(error) + ")");
}

std::filesystem::path copy_of_pipe(const std::filesystem::path& file) {
  static int counter = 0;
  const std::filesystem::path copy = std::filesystem::temp_directory_path() /
                                     ("nibrig-pipe-" + std::to_string(::getpid()) + "-" +
                                      std::to_string(counter++));
  const int in = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (in < 0) pipe_failure(file, "cannot open for reading", errno);
  const int out = ::open(copy.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (out < 0) {
    const int error = errno;
    ::close(in);
    pipe_failure(file, "cannot keep what the pipe carries in " + copy.string(), error);
  }
  track_temporary(copy);
  const auto give_up = [&](const std::string& what, int error) {
    ::close(in);
    ::close(out);
    ::unlink(copy.c_str());
    untrack_temporary(copy);
    if (error != 0) pipe_failure(file, what, error);
    throw FormatError(file, "", what);
  };
  std::size_t total = 0;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(in, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) give_up("cannot read the pipe", errno);
    if (n == 0) break;
    total += static_cast<std::size_t>(n);
    if (total > kMaxPipedBytes)
      give_up("the pipe carries more than " + byte_bound_text(kMaxPipedBytes) +
                  ", more than any input nibrig reads; is the right command piped in?",
              0);
    for (ssize_t done = 0; done < n;) {
      const ssize_t w = ::write(out, buffer + done, static_cast<std::size_t>(n - done));
      if (w < 0 && errno == EINTR) continue;
      if (w < 0) give_up("cannot keep what the pipe carries in " + copy.string(), errno);
      done += w;
    }
  }
  ::close(in);
  if (::close(out) != 0) give_up("cannot keep what the pipe carries in " + copy.string(), errno);
  return copy;
}

}  // namespace

std::filesystem::path readable_path(const std::filesystem::path& file) {
  struct stat info {};
  if (::stat(file.c_str(), &info) != 0 || !S_ISFIFO(info.st_mode)) return file;
  Spools& s = spools();
  std::lock_guard lock(s.mutex);
  const auto found = s.copies.find(file.string());
  if (found != s.copies.end()) return found->second;
  return s.copies.emplace(file.string(), copy_of_pipe(file)).first->second;
}

}  // namespace nibrig::model::io
