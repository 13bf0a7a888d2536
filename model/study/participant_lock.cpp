#include "model/study/participant_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "model/io/utc_time.hpp"
#include "model/study/response_log.hpp"

namespace nibrig::model::study {

namespace {

std::string holder_noted_in(int fd) {
  char text[256] = {};
  const ssize_t n = ::pread(fd, text, sizeof text - 1, 0);
  std::string holder = n > 0 ? std::string(text, static_cast<std::size_t>(n)) : "";
  while (!holder.empty() && (holder.back() == '\n' || holder.back() == '\r')) holder.pop_back();
  return holder.empty() ? "another process" : holder;
}

}  // namespace

ParticipantLock::ParticipantLock(const std::filesystem::path& study, const std::string& participant)
    : file_(study / kParticipantsFolder / (participant + ".lock")) {
  // A holder removes the file before it lets go: a lock taken on a file that was removed (or
  // replaced) meanwhile locks nothing another session sees, so it is taken again on the file
  // there now. A few rounds at most: each means another session ended just then.
  for (int attempt = 0; attempt < 8; ++attempt) {
    fd_ = ::open(file_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0)
      throw std::runtime_error(file_.string() + ": cannot create the participant's lock (" +
                               std::strerror(errno) + ")");
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      const std::string holder = error == EWOULDBLOCK ? holder_noted_in(fd_) : "";
      ::close(fd_);
      fd_ = -1;
      if (error == EWOULDBLOCK)
        throw std::runtime_error("participant " + participant + " is in a session already (" +
                                 holder + "): one session per participant at a time; wait for it "
                                 "to end, or stop it");
      throw std::runtime_error(file_.string() + ": cannot lock (" + std::strerror(error) + ")");
    }
    struct stat held {}, named {};
    if (::fstat(fd_, &held) == 0 && ::stat(file_.c_str(), &named) == 0 && held.st_dev == named.st_dev &&
        held.st_ino == named.st_ino)
      break;
    ::close(fd_);
    fd_ = -1;
  }
  if (fd_ < 0) throw std::runtime_error(file_.string() + ": the lock file kept being replaced; try again");
  char host[256] = {};
  ::gethostname(host, sizeof host - 1);
  const std::string note = "pid " + std::to_string(::getpid()) + " on host " + host + " since " +
                           io::now_utc_iso8601() + "\n";
  // The note is for people; a failure to write it leaves the lock, which is what matters.
  if (::ftruncate(fd_, 0) == 0) {
    [[maybe_unused]] const ssize_t written = ::pwrite(fd_, note.data(), note.size(), 0);
  }
}

ParticipantLock::~ParticipantLock() {
  if (fd_ < 0) return;
  // Removed while still held, so that no session can lock this file after it is gone.
  ::unlink(file_.c_str());
  ::close(fd_);  // closing the last descriptor releases the flock
}

}  // namespace nibrig::model::study
