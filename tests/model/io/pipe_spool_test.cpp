#include "model/io/pipe_spool.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>
#include <string>
#include <thread>

#include "model/io/format_error.hpp"
#include "model/io/json_fields.hpp"
#include "model/io/triplets.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::io {
namespace {

namespace fs = std::filesystem;

// `cat judgments.csv | nibrig space fit /dev/stdin` said "empty file": the reader looks at the
// header to tell the format, then opens the file again. A FIFO is what the shell's pipe is.
TEST(PipeSpool, ATripletFilePipedInIsReadWhole) {
  const fs::path folder = test::scratch_dir("pipe_spool_triplets");
  const fs::path fifo = folder / "stdin";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::thread writer([&] {
    std::ofstream(fifo) << "reference,a,b,count_a,count_b\ncryon,stab,vero,3,1\nstab,vero,cryon,0,2\n";
  });
  const TripletSet set = read_triplets(fifo);
  writer.join();
  EXPECT_EQ(set.stimuli, (std::vector<std::string>{"cryon", "stab", "vero"}));
  ASSERT_EQ(set.triplets.size(), 2u);
  EXPECT_EQ(set.triplets[1].count_b, 2);
  // The copy is the pipe's for the rest of the process: read again, the same content.
  EXPECT_EQ(read_triplets(fifo).triplets.size(), 2u);
  const fs::path copy = readable_path(fifo);
  EXPECT_NE(copy, fifo);
  EXPECT_TRUE(fs::is_regular_file(copy));
}

TEST(PipeSpool, ARegularFileOrADeviceIsOpenedItself) {
  const fs::path folder = test::scratch_dir("pipe_spool_regular");
  std::ofstream(folder / "a.json") << "{}";
  EXPECT_EQ(readable_path(folder / "a.json"), folder / "a.json");
  EXPECT_EQ(readable_path("/dev/zero"), "/dev/zero");
}

std::size_t copies_of_this_process() {
  const std::string prefix = "nibrig-pipe-" + std::to_string(::getpid()) + "-";
  std::size_t n = 0;
  for (const auto& entry : fs::directory_iterator(fs::temp_directory_path()))
    n += entry.path().filename().string().rfind(prefix, 0) == 0;
  return n;
}

TEST(PipeSpool, APipeThatDoesNotEndIsRefusedAtTheBound) {
  ::signal(SIGPIPE, SIG_IGN);  // the writer learns the reader gave up from EPIPE
  const std::size_t copies_before = copies_of_this_process();
  const fs::path folder = test::scratch_dir("pipe_spool_endless");
  const fs::path fifo = folder / "endless";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::thread writer([&] {
    std::ofstream out(fifo, std::ios::binary);
    const std::string block(1 << 20, '[');
    for (std::size_t i = 0; i <= (kMaxPipedBytes >> 20) && out; ++i) out << block;
  });
  try {
    json_fields::parse_file(fifo);
    ADD_FAILURE() << "an endless pipe was read";
  } catch (const FormatError& e) {
    EXPECT_EQ(e.file(), fifo);
    EXPECT_NE(std::string(e.what()).find("256 MiB"), std::string::npos) << e.what();
  }
  writer.join();  // the reader closed its end: the writer's stream fails and it stops
  EXPECT_EQ(copies_of_this_process(), copies_before) << "the refused copy is removed";
}

}  // namespace
}  // namespace nibrig::model::io
