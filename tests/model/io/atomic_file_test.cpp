#include "model/io/atomic_file.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>

#include "tests/support/test_paths.hpp"

namespace nibrig::model::io {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::size_t entries(const fs::path& folder) {
  return static_cast<std::size_t>(std::distance(fs::directory_iterator(folder), {}));
}

// Each kind of name an output can be given, and what must become of it: a device node or a symlink
// must not become a regular file. `after` is what the name must still be.
struct Case {
  const char* what;
  void (*make)(const fs::path& name, const fs::path& folder);
  fs::file_type after;
  bool written_through_link;  // the content lands in the link's target
};

void nothing(const fs::path&, const fs::path&) {}
void regular(const fs::path& name, const fs::path&) { std::ofstream(name) << "old"; }
void link_to_file(const fs::path& name, const fs::path& folder) {
  std::ofstream(folder / "target.json") << "old";
  fs::create_symlink("target.json", name);
}
void dangling_link(const fs::path& name, const fs::path& folder) {
  fs::create_symlink(folder / "sub" / "new.json", name);
  fs::create_directory(folder / "sub");
}
void link_chain(const fs::path& name, const fs::path& folder) {
  std::ofstream(folder / "target.json") << "old";
  fs::create_symlink("target.json", folder / "middle");
  fs::create_symlink("middle", name);
}
void link_to_null(const fs::path& name, const fs::path&) { fs::create_symlink("/dev/null", name); }
void fifo(const fs::path& name, const fs::path&) { ASSERT_EQ(::mkfifo(name.c_str(), 0600), 0); }

TEST(OutputFile, ANameIsWrittenAsWhatItIsAndNeverReplacedByAnotherKindOfFile) {
  const Case cases[] = {
      {"a new name", nothing, fs::file_type::regular, false},
      {"a regular file", regular, fs::file_type::regular, false},
      {"a link to a file", link_to_file, fs::file_type::symlink, true},
      {"a dangling link", dangling_link, fs::file_type::symlink, true},
      {"a chain of links", link_chain, fs::file_type::symlink, true},
      {"a link to /dev/null", link_to_null, fs::file_type::symlink, false},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    const fs::path folder = test::scratch_dir(std::string("atomic_file_") + c.what);
    const fs::path name = folder / "out.json";
    c.make(name, folder);
    write_file_atomically(name, "new");
    EXPECT_EQ(fs::symlink_status(name).type(), c.after);
    if (c.after != fs::file_type::symlink || c.written_through_link) EXPECT_EQ(read(name), "new");
    if (c.written_through_link) EXPECT_EQ(read(fs::canonical(name)), "new");
    // No temporary is left beside the name or its target.
    for (const auto& entry : fs::recursive_directory_iterator(folder))
      EXPECT_EQ(entry.path().string().find(".tmp-"), std::string::npos) << entry.path();
  }
}

TEST(OutputFile, APipeIsWrittenAsAStream) {
  const fs::path folder = test::scratch_dir("atomic_file_fifo");
  const fs::path name = folder / "pipe";
  fifo(name, folder);
  std::string received;
  std::thread reader([&] { received = read(name); });
  write_file_atomically(name, "streamed");
  reader.join();
  EXPECT_EQ(received, "streamed");
  EXPECT_EQ(fs::symlink_status(name).type(), fs::file_type::fifo);
  EXPECT_EQ(entries(folder), 1u);
}

TEST(OutputFile, ACharacterDeviceIsWrittenInPlaceAndItsErrorsReported) {
  write_file_atomically("/dev/null", "discarded");
  EXPECT_EQ(fs::status("/dev/null").type(), fs::file_type::character);
  try {
    write_file_atomically("/dev/full", "no room");
    FAIL() << "/dev/full took the content";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/dev/full"), std::string::npos) << e.what();
  }
  EXPECT_EQ(fs::status("/dev/full").type(), fs::file_type::character);
}

TEST(OutputFile, WhatCannotBeWrittenIsRefusedBeforeAnythingIsWritten) {
  const fs::path folder = test::scratch_dir("atomic_file_refused");
  for (const fs::path& name : {folder, fs::path("/dev/loop0")}) {
    if (!fs::exists(name)) continue;  // not every machine has a loop device node
    SCOPED_TRACE(name.string());
    EXPECT_THROW(output_target(name), std::runtime_error);
  }
  EXPECT_EQ(entries(folder), 0u);
}

// A temporary written for a stream target cannot sit beside /dev/stdout: it goes to the temporary
// folder and is removed once copied.
TEST(OutputFile, AFinishedTemporaryIsCopiedIntoAStreamAndRemoved) {
  const OutputTarget target = output_target("/dev/null");
  ASSERT_TRUE(target.stream);
  const fs::path temporary = temporary_beside(target);
  std::ofstream(temporary) << "figure";
  commit_output(temporary, target);
  EXPECT_FALSE(fs::exists(temporary));
}

}  // namespace
}  // namespace nibrig::model::io
