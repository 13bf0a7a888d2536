// One session per participant at a time. Two `experiment run --resume` of one participant at once
// both read the same answers and both appended the next trials: 25 duplicates, and a responses file
// the report then refused. A session holds an exclusive flock(2) on <study>/participants/<id>.lock
// for its whole life; the kernel releases it when the process ends, even by kill -9, so a crash
// never leaves a participant locked. The file notes who holds it, for the refusal's message, and is
// removed when the session ends (a crash leaves it behind unlocked: the next session takes it).
#pragma once

#include <filesystem>
#include <string>

namespace nibrig::model::study {

class ParticipantLock {
 public:
  // Throws std::runtime_error naming the participant and the holder ("pid 4242 on host lab-3 since
  // 2026-11-27T01:02:03Z") when another session holds it, or naming the file when it cannot be made.
  ParticipantLock(const std::filesystem::path& study, const std::string& participant);
  // Removes the lock file, then releases the lock.
  ~ParticipantLock();
  ParticipantLock(const ParticipantLock&) = delete;
  ParticipantLock& operator=(const ParticipantLock&) = delete;

 private:
  std::filesystem::path file_;
  int fd_ = -1;
};

}  // namespace nibrig::model::study
