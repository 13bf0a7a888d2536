// A folder result (the demo's report) is built beside the folder named and swapped in whole: a run
// that fails or is killed leaves the earlier report as it was, and a folder that holds something
// else is refused before anything is made.
#include "model/io/folder_result.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <stdexcept>

#include "tests/model/io/io_test_files.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::io {
namespace {

namespace fs = std::filesystem;

std::size_t entries_in(const fs::path& folder) {
  return static_cast<std::size_t>(std::distance(fs::directory_iterator(folder), fs::directory_iterator()));
}

TEST(FolderResult, ACommittedResultReplacesTheEarlierOneWhole) {
  const auto dir = nibrig::test::scratch_dir("folder_result_commit");
  {
    FolderResult earlier(dir / "report", "SUMMARY.json");
    nibrig::test::write_text(earlier.work() / "SUMMARY.json", "{}");
    nibrig::test::write_text(earlier.work() / "old_only.txt", "old");
    earlier.commit();
  }
  {
    FolderResult result(dir / "report", "SUMMARY.json");
    EXPECT_EQ(result.work().parent_path(), dir);
    nibrig::test::write_text(result.work() / "SUMMARY.json", "{\"new\":1}");
    // While it is built, the earlier report is whole.
    EXPECT_TRUE(fs::exists(dir / "report" / "old_only.txt"));
    result.commit();
  }
  EXPECT_FALSE(fs::exists(dir / "report" / "old_only.txt"));
  EXPECT_TRUE(fs::exists(dir / "report" / "SUMMARY.json"));
  EXPECT_EQ(entries_in(dir), 1u) << "the work folder and the earlier report are gone";
}

// The trial's `nibrig demo -o out/dm_old` over an earlier demo beside which a person kept notes.
TEST(FolderResult, AnEarlierResultHoldingAPersonsFilesIsRefusedAndKept) {
  const auto dir = nibrig::test::scratch_dir("folder_result_persons");
  const auto earlier_report = [&] {
    fs::remove_all(dir / "report");
    FolderResult earlier(dir / "report", "SUMMARY.json");
    nibrig::test::write_text(earlier.work() / "SUMMARY.json", "{}");
    fs::create_directories(earlier.work() / "spectra");
    nibrig::test::write_text(earlier.work() / "spectra" / "a.png", "png");
    earlier.commit();
  };
  const auto refusal = [&] {
    try {
      FolderResult again(dir / "report", "SUMMARY.json");
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  earlier_report();
  nibrig::test::write_text(dir / "report" / "notes.txt", "mine");
  fs::create_directories(dir / "report" / "mine");
  std::string message = refusal();
  EXPECT_NE(message.find("notes.txt"), std::string::npos) << message;
  EXPECT_NE(message.find("mine"), std::string::npos) << message;
  EXPECT_TRUE(fs::exists(dir / "report" / "notes.txt"));
  EXPECT_TRUE(fs::exists(dir / "report" / "spectra" / "a.png"));

  earlier_report();  // a report file the person edited is theirs now
  nibrig::test::write_text(dir / "report" / "spectra" / "a.png", "an edited png");
  message = refusal();
  EXPECT_NE(message.find("spectra/a.png"), std::string::npos) << message;

  fs::remove_all(dir / "report");  // one without the list (an older nibrig's, or hand-made)
  fs::create_directories(dir / "report");
  nibrig::test::write_text(dir / "report" / "SUMMARY.json", "{}");
  EXPECT_NE(refusal().find(kFolderResultFiles), std::string::npos);
  EXPECT_EQ(entries_in(dir), 1u) << "nothing made beside it";
}

TEST(FolderResult, AFailedRunLeavesTheEarlierResultAndNoWorkFolder) {
  const auto dir = nibrig::test::scratch_dir("folder_result_fail");
  fs::create_directories(dir / "report");
  nibrig::test::write_text(dir / "report" / "SUMMARY.json", "{}");
  try {
    FolderResult result(dir / "report", "SUMMARY.json");
    nibrig::test::write_text(result.work() / "half.txt", "half");
    throw std::runtime_error("the run failed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(entries_in(dir / "report"), 1u);
  EXPECT_EQ(entries_in(dir), 1u);
}

TEST(FolderResult, AKilledRunsWorkFolderIsClearedByTheNextRun) {
  const auto dir = nibrig::test::scratch_dir("folder_result_killed");
  const pid_t child = fork();
  if (child == 0) {
    FolderResult result(dir / "report", "SUMMARY.json");
    nibrig::test::write_text(result.work() / "half.txt", "half");
    _exit(0);  // like a kill: no destructor runs
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_EQ(entries_in(dir), 1u) << "the killed run's work folder";
  FolderResult next(dir / "report", "SUMMARY.json");
  EXPECT_EQ(entries_in(dir), 1u) << "only this run's work folder is left";
}

TEST(FolderResult, AFolderHoldingSomethingElseIsRefusedUntouched) {
  const auto dir = nibrig::test::scratch_dir("folder_result_refuse");
  fs::create_directories(dir / "thesis");
  nibrig::test::write_text(dir / "thesis" / "chapter1.tex", "x");
  nibrig::test::write_text(dir / "a_file", "x");
  for (const fs::path& target : {dir / "thesis", dir / "a_file"}) {
    try {
      FolderResult result(target, "SUMMARY.json");
      ADD_FAILURE() << target << " was accepted";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(target.string()), std::string::npos) << e.what();
    }
  }
  EXPECT_TRUE(fs::exists(dir / "thesis" / "chapter1.tex"));
  EXPECT_EQ(entries_in(dir), 2u);
  // An empty folder and a new name are fine.
  fs::create_directories(dir / "empty");
  EXPECT_NO_THROW(FolderResult(dir / "empty", "SUMMARY.json"));
  EXPECT_NO_THROW(FolderResult(dir / "new", "SUMMARY.json"));
}

}  // namespace
}  // namespace nibrig::model::io
