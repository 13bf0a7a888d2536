#include "model/io/interrupt_cleanup.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "model/io/atomic_file.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::io {
namespace {

namespace fs = std::filesystem;

// A child process makes a temporary file and a work folder as the writers do, then is stopped by
// `signal`: what it tracked must be gone, and it must still end by that signal (a shell then
// reports 128 + signal, as for any program stopped by Ctrl-C).
void expect_removed_when_stopped_by(int signal, const char* name) {
  const fs::path folder = test::scratch_dir(std::string("interrupt_cleanup_") + name);
  std::ofstream(folder / "mine.txt") << "a person's file";
  const fs::path work = folder / ".report.partial-1";
  const OutputTarget target{folder / "r.wav", false};
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    remove_temporaries_on_signals();
    const fs::path temporary = temporary_beside(target);
    std::ofstream(temporary) << "half a render";
    fs::create_directories(work / "spectra" / "deeper");
    std::ofstream(work / "spectra" / "deeper" / "a.png") << "png";
    std::ofstream(work / "SUMMARY.json") << "{}";
    track_temporary(work);
    ::raise(signal);
    ::_exit(3);  // not reached: the handler ends the process by the signal
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status)) << "exit status " << WEXITSTATUS(status);
  EXPECT_EQ(WTERMSIG(status), signal);
  std::vector<std::string> left;
  for (const auto& entry : fs::directory_iterator(folder)) left.push_back(entry.path().filename());
  EXPECT_EQ(left, std::vector<std::string>{"mine.txt"}) << "only the person's own file stays";
}

TEST(InterruptCleanup, CtrlCRemovesTemporaryFilesAndWorkFolders) {
  expect_removed_when_stopped_by(SIGINT, "int");
}

TEST(InterruptCleanup, TerminationAndHangUpRemoveThemToo) {
  expect_removed_when_stopped_by(SIGTERM, "term");
  expect_removed_when_stopped_by(SIGHUP, "hup");
}

TEST(InterruptCleanup, AFinishedOutputIsNoLongerTracked) {
  const fs::path folder = test::scratch_dir("interrupt_cleanup_finished");
  const int before = tracked_temporaries();
  write_file_atomically(folder / "done.json", "{}\n");
  EXPECT_EQ(tracked_temporaries(), before);
  const OutputTarget target{folder / "held.json", false};
  const fs::path temporary = temporary_beside(target);
  EXPECT_EQ(tracked_temporaries(), before + 1);
  std::ofstream(temporary) << "x";
  commit_output(temporary, target);
  EXPECT_EQ(tracked_temporaries(), before);
}

}  // namespace
}  // namespace nibrig::model::io
