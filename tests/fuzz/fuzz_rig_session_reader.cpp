// libFuzzer target for read_rig_session: the input is session.json, a NUL byte, then WAV bytes
// used for all four streams (so one set of rates in the JSON fits them all). Each input is read
// both as a finished folder and as a .partial one. A FormatError is the expected answer to bad bytes;
// anything else (another exception, a crash, a sanitizer report) is a bug in the reader.
//
// Build and run (clang):
//   clang++ -std=c++20 -g -O1 -fsanitize=fuzzer,address -I. tests/fuzz/fuzz_rig_session_reader.cpp \
//     model/io/*.cpp -lz -lsndfile -o /tmp/fuzz_session
//   /tmp/fuzz_session -max_total_time=60 /tmp/session_corpus tests/fuzz/corpus/rig_session_reader
// (the first folder receives new inputs, so the seeds in the repository stay as they are).
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "model/io/format_error.hpp"
#include "model/io/rig_session.hpp"
#include "tests/fuzz/scratch_folder.hpp"

namespace {

namespace fs = std::filesystem;
namespace io = nibrig::model::io;

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

  const nibrig::test::ScratchFolder scratch("nibrig-fuzz-session");
  for (const char* name : {"s", "s.partial"}) {
    const fs::path folder = scratch.path() / name;
    fs::create_directories(folder);
    write_file(folder / io::kSessionJson, data, split);
    for (const char* stream :
         {io::kAccelerationWav, io::kSpeedWav, io::kNormalForceWav, io::kTangentialForceWav}) {
      write_file(folder / stream, wav, end);
    }
    try {
      io::read_rig_session(folder);
    } catch (const io::FormatError&) {
      // The reader recognised bad input and said so.
    }
  }
  return 0;
}
