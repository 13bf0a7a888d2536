#include "model/io/job_files.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "model/io/atomic_file.hpp"
#include "model/io/bounded_read.hpp"
#include "model/io/text_lines.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::io {
namespace {

namespace fs = std::filesystem;

std::string content_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string read_whole(const fs::path& file) {
  return read_bounded_file(file, 1 << 20, "a test file", "a few bytes");
}

std::string refusal_of(const fs::path& output) {
  try {
    write_file_atomically(output, "new\n");
  } catch (const OutputFileError& e) {
    return e.what();
  }
  return {};
}

TEST(JobFiles, AnOutputOntoAFileTheJobReadIsRefusedNamingBothAndTheFileKept) {
  const fs::path folder = test::scratch_dir("job_files_same");
  std::ofstream(folder / "stylus.json") << "input\n";
  const JobFiles job;
  read_whole(folder / "stylus.json");
  const std::string message = refusal_of(folder / "stylus.json");
  EXPECT_NE(message.find((folder / "stylus.json").string()), std::string::npos) << message;
  EXPECT_NE(message.find("read as an input"), std::string::npos) << message;
  EXPECT_EQ(content_of(folder / "stylus.json"), "input\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(folder), {}), 1) << "no temporary file left";
}

TEST(JobFiles, ALinkOrAHardLinkToAnInputIsTheInput) {
  const fs::path folder = test::scratch_dir("job_files_links");
  std::ofstream(folder / "catalog.json") << "catalog\n";
  fs::create_symlink("catalog.json", folder / "s-body.stl");
  fs::create_hard_link(folder / "catalog.json", folder / "hard.json");
  const JobFiles job;
  TextLineReader reader(folder / "catalog.json");  // the line reader notes what it opens too
  for (const char* name : {"s-body.stl", "hard.json"}) {
    const std::string message = refusal_of(folder / name);
    EXPECT_NE(message.find("catalog.json"), std::string::npos) << name << ": " << message;
  }
  EXPECT_EQ(content_of(folder / "catalog.json"), "catalog\n");
  EXPECT_TRUE(fs::is_symlink(folder / "s-body.stl"));
}

TEST(JobFiles, OutsideAJobAndAfterItNothingIsRefused) {
  // A Python session loads a file in one call and saves over it in another: two jobs.
  const fs::path folder = test::scratch_dir("job_files_outside");
  std::ofstream(folder / "space.json") << "old\n";
  read_whole(folder / "space.json");
  EXPECT_EQ(refusal_of(folder / "space.json"), "");
  {
    const JobFiles job;
    read_whole(folder / "space.json");
  }
  EXPECT_EQ(refusal_of(folder / "space.json"), "");
  EXPECT_EQ(content_of(folder / "space.json"), "new\n");
}

TEST(JobFiles, WhatTheJobWroteAndReadBackItMayWriteAgain) {
  const fs::path folder = test::scratch_dir("job_files_own");
  const JobFiles job;
  write_file_atomically(folder / "summary.json", "first\n");
  read_whole(folder / "summary.json");
  EXPECT_EQ(refusal_of(folder / "summary.json"), "");
  EXPECT_EQ(content_of(folder / "summary.json"), "new\n");
}

TEST(JobFiles, AnInputReleasedToBeReplacedOnPurposeMayBeWritten) {
  const fs::path folder = test::scratch_dir("job_files_release");
  const fs::path file = folder / "lab-pla.json";
  std::ofstream(file) << "old\n";
  JobFiles job;
  read_whole(file);
  EXPECT_NE(refusal_of(file), "");
  release_input(file);
  EXPECT_EQ(refusal_of(file), "");
  EXPECT_EQ(content_of(file), "new\n");
}

TEST(OutputSet, WithoutCommitNoneOfItsFilesAppearAndEarlierOnesStay) {
  const fs::path folder = test::scratch_dir("output_set_abandoned");
  std::ofstream(folder / "s.3mf") << "old 3mf";
  std::ofstream(folder / "s.json") << "old recipe";
  {
    const OutputSet set;
    write_file_atomically(folder / "s.3mf", "new 3mf");
    write_file_atomically(folder / "s-body.stl", "new stl");
    EXPECT_EQ(content_of(folder / "s.3mf"), "old 3mf") << "held back until the set commits";
  }
  EXPECT_EQ(content_of(folder / "s.3mf"), "old 3mf");
  EXPECT_EQ(content_of(folder / "s.json"), "old recipe");
  EXPECT_FALSE(fs::exists(folder / "s-body.stl"));
  EXPECT_EQ(std::distance(fs::directory_iterator(folder), {}), 2) << "no temporary file left";
}

TEST(OutputSet, ARefusalHalfwayLeavesTheEarlierSetWhole) {
  const fs::path folder = test::scratch_dir("output_set_refused");
  std::ofstream(folder / "stylus.json") << "prediction\n";
  std::ofstream(folder / "stylus.3mf") << "old 3mf";
  const JobFiles job;
  read_whole(folder / "stylus.json");
  try {
    const OutputSet set;
    write_file_atomically(folder / "stylus.3mf", "new 3mf");
    write_file_atomically(folder / "stylus.json", "recipe");  // the recipe onto the prediction
    FAIL() << "the recipe replaced the prediction it was made from";
  } catch (const OutputFileError&) {
  }
  EXPECT_EQ(content_of(folder / "stylus.json"), "prediction\n");
  EXPECT_EQ(content_of(folder / "stylus.3mf"), "old 3mf");
  EXPECT_EQ(std::distance(fs::directory_iterator(folder), {}), 2) << "no temporary file left";
}

TEST(OutputSet, CommitPutsEveryFileInPlace) {
  const fs::path folder = test::scratch_dir("output_set_committed");
  std::ofstream(folder / "s.3mf") << "old 3mf";
  OutputSet set;
  write_file_atomically(folder / "s.3mf", "new 3mf");
  write_file_atomically(folder / "s.json", "new recipe");
  set.commit();
  EXPECT_EQ(content_of(folder / "s.3mf"), "new 3mf");
  EXPECT_EQ(content_of(folder / "s.json"), "new recipe");
  EXPECT_EQ(std::distance(fs::directory_iterator(folder), {}), 2);
}

TEST(OutputSet, TwoOfItsFilesTheSameIsRefused) {
  const fs::path folder = test::scratch_dir("output_set_twice");
  const OutputSet set;
  write_file_atomically(folder / "a.json", "one");
  EXPECT_THROW(write_file_atomically(folder / "a.json", "two"), OutputFileError);
}

}  // namespace
}  // namespace nibrig::model::io
