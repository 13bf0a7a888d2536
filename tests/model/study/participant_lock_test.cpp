// The participant's lock: held for a session's life, refused to a second session, and its file gone
// once the session ends (a study folder after a session held a stale P01.lock), while a file a
// crashed session left behind is taken over.
#include "model/study/participant_lock.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>

#include "model/study/response_log.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::study {
namespace {

std::filesystem::path lock_test_study(const char* name) {
  const auto study = nibrig::test::scratch_dir(name) / "study";
  std::filesystem::create_directories(study / kParticipantsFolder);
  return study;
}

TEST(ParticipantLock, IsHeldForItsLifeAndLeavesNoFileBehind) {
  const auto study = lock_test_study("participant_lock_life");
  const auto file = study / kParticipantsFolder / "P01.lock";
  {
    ParticipantLock first(study, "P01");
    EXPECT_TRUE(std::filesystem::exists(file));
    try {
      ParticipantLock second(study, "P01");
      ADD_FAILURE() << "two locks of P01 at once";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("pid " + std::to_string(::getpid())), std::string::npos) << e.what();
    }
    EXPECT_TRUE(std::filesystem::exists(file)) << "a refused session removed the holder's file";
    ParticipantLock other(study, "P02");  // another participant is not locked out
  }
  EXPECT_FALSE(std::filesystem::exists(file));
  EXPECT_FALSE(std::filesystem::exists(study / kParticipantsFolder / "P02.lock"));
  // Taken again at once, and again gone after.
  { ParticipantLock again(study, "P01"); }
  EXPECT_FALSE(std::filesystem::exists(file));
}

TEST(ParticipantLock, AFileACrashedSessionLeftIsTakenOverAndRemoved) {
  const auto study = lock_test_study("participant_lock_crashed");
  const auto file = study / kParticipantsFolder / "P01.lock";
  std::ofstream(file) << "pid 1 on host gone since 2026-01-01T00:00:00Z\n";  // no process holds it
  {
    ParticipantLock lock(study, "P01");
    std::ifstream in(file);
    std::string note;
    std::getline(in, note);
    EXPECT_EQ(note.rfind("pid " + std::to_string(::getpid()) + " on host ", 0), 0u) << note;
  }
  EXPECT_FALSE(std::filesystem::exists(file));
}

}  // namespace
}  // namespace nibrig::model::study
