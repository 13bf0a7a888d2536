// libFuzzer target for read_session: the input is session.json, a NUL byte, then WAV bytes used for
// all four streams (so one set of rates in the JSON fits them all). Each input is read both as a
// finished folder and as a .partial one. A FormatError is the expected answer to bad bytes;
// anything else (another exception, a crash, a sanitizer report) is a bug in the reader.
//
// Build and run (clang):
//   clang++ -std=c++20 -g -O1 -fsanitize=fuzzer,address -I. tests/fuzz/fuzz_session_reader.cpp \
//     model/io/*.cpp -lz -lsndfile -o /tmp/fuzz_session
//   /tmp/fuzz_session -max_total_time=60 /tmp/session_corpus tests/fuzz/corpus/session
// (the first folder receives new inputs, so the seeds in the repository stay as they are).
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "model/io/format_error.hpp"
#include "model/io/session.hpp"

namespace {

namespace fs = std::filesystem;
namespace io = nibrig::model::io;

// A fresh folder for one input, removed afterwards; mkdtemp keeps parallel jobs (-jobs=N) apart.
// Per input rather than per process because libFuzzer ends with _Exit, which skips any cleanup
// registered for exit. In memory when possible: rewriting files on ext4 flushes them to disk on
// close, which slows fuzzing ~50x.
class ScratchFolder {
 public:
  ScratchFolder() {
    std::error_code ec;
    const fs::path base = std::getenv("TMPDIR") == nullptr && fs::is_directory("/dev/shm", ec)
                              ? fs::path("/dev/shm")
                              : fs::temp_directory_path();
    std::string pattern = (base / "nibrig-fuzz-session-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) std::abort();  // the harness failed, not a reader
    path_ = pattern;
  }
  ~ScratchFolder() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

void write_file(const fs::path& file, const std::uint8_t* begin, const std::uint8_t* end) {
  std::ofstream out(file, std::ios::binary);
  out.write(reinterpret_cast<const char*>(begin), static_cast<std::streamsize>(end - begin));
  if (!out) std::abort();  // the harness itself failed, not the reader
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::uint8_t* end = data + size;
  const std::uint8_t* split = std::find(data, end, std::uint8_t{0});
  const std::uint8_t* wav = split == end ? end : split + 1;

  const ScratchFolder scratch;
  for (const char* name : {"s", "s.partial"}) {
    const fs::path folder = scratch.path() / name;
    fs::create_directories(folder);
    write_file(folder / io::kSessionJson, data, split);
    for (const char* stream :
         {io::kAccelerationWav, io::kSpeedWav, io::kNormalForceWav, io::kTangentialForceWav}) {
      write_file(folder / stream, wav, end);
    }
    try {
      io::read_session(folder);
    } catch (const io::FormatError&) {
      // The reader recognised bad input and said so.
    }
  }
  return 0;
}
