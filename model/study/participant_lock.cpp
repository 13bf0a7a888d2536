#include "model/study/participant_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
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

ParticipantLock::ParticipantLock(const std::filesystem::path& study, const std::string& participant) {
  const std::filesystem::path file = study / kParticipantsFolder / (participant + ".lock");
  fd_ = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw std::runtime_error(file.string() + ": cannot create the participant's lock (" +
                             std::strerror(errno) + ")");
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    const std::string holder = error == EWOULDBLOCK ? holder_noted_in(fd_) : "";
    ::close(fd_);
    if (error == EWOULDBLOCK)
      throw std::runtime_error("participant " + participant + " is in a session already (" +
                               holder + "): one session per participant at a time; wait for it "
                               "to end, or stop it");
    throw std::runtime_error(file.string() + ": cannot lock (" + std::strerror(error) + ")");
  }
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
  if (fd_ >= 0) ::close(fd_);  // closing the last descriptor releases the flock
}

}  // namespace nibrig::model::study
