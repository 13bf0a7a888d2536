// libFuzzer target for the text readers of model/io: the input bytes become a file (gzip or plain,
// zlib tells them apart) read as a friction recording, an accelerometer recording, an artist's
// trajectory and each kind of triplet file. A FormatError is the expected answer to bad bytes;
// anything else (another exception, a crash, a sanitizer report) is a bug in a reader.
//
// Build and run (clang):
//   clang++ -std=c++20 -g -O1 -fsanitize=fuzzer,address -I. tests/fuzz/fuzz_csv_readers.cpp \
//     model/io/*.cpp -lz -lsndfile -o /tmp/fuzz_csv
//   /tmp/fuzz_csv -max_total_time=60 /tmp/csv_corpus tests/fuzz/corpus/csv_readers
// (the first folder receives new inputs, so the seeds in the repository stay as they are).
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "model/io/format_error.hpp"
#include "model/io/paper_drawing.hpp"
#include "model/io/paper_friction.hpp"
#include "model/io/paper_recording.hpp"
#include "model/io/paper_vibration.hpp"
#include "model/io/triplets.hpp"
#include "tests/fuzz/scratch_folder.hpp"

namespace {

namespace fs = std::filesystem;
namespace io = nibrig::model::io;

void write_file(const fs::path& file, const std::uint8_t* data, std::size_t size) {
  std::ofstream out(file, std::ios::binary);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  if (!out) std::abort();  // the harness itself failed, not the reader
}

template <typename Read>
void expect_only_format_errors(const fs::path& file, Read read) {
  try {
    read(file);
  } catch (const io::FormatError&) {
    // The reader recognised bad input and said so.
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const nibrig::test::ScratchFolder scratch("nibrig-fuzz-csv");
  const fs::path& dir = scratch.path();
  // File names the name parsers accept, so the fuzzer reaches the contents.
  const fs::path friction = dir / "p2h_note_2.2N_14_1.csv";
  const fs::path vibration = dir / "arm_vero_1_glass.csv";
  const fs::path drawing = dir / "pen_paper_cube.csv";
  const fs::path triplets = dir / "triplets.csv";
  const fs::path lagunas = dir / "answers.json";
  for (const fs::path* file : {&friction, &vibration, &drawing, &triplets, &lagunas}) {
    write_file(*file, data, size);
  }
  // The readers are overloaded (by name, or with what the caller states): lambdas pick one each.
  expect_only_format_errors(friction, [](const fs::path& f) { return io::read_paper_friction(f); });
  expect_only_format_errors(vibration, [](const fs::path& f) { return io::read_paper_vibration(f); });
  // Any file name: the format from the header, the tool and surface stated (nibrig measure --tool).
  const fs::path unnamed = dir / "recording.csv";
  write_file(unnamed, data, size);
  expect_only_format_errors(unnamed, io::paper_format_from_header);
  const io::StatedRecording stated{"mixA", "note", 2.2, 13.7};
  expect_only_format_errors(unnamed, [&](const fs::path& f) { return io::read_paper_vibration(f, stated); });
  expect_only_format_errors(unnamed, [&](const fs::path& f) { return io::read_paper_friction(f, stated); });
  expect_only_format_errors(drawing, io::read_paper_drawing);
  expect_only_format_errors(triplets, [](const fs::path& f) { return io::read_triplets(f); });
  expect_only_format_errors(triplets, io::read_triplet_csv);
  expect_only_format_errors(triplets, io::read_salmon_csv);
  expect_only_format_errors(lagunas, [](const fs::path& f) { return io::read_lagunas_json(f); });
  // Names given by a script instead of read beside the file: an id past them is a format error.
  expect_only_format_errors(lagunas, [](const fs::path& f) {
    return io::read_lagunas_json(f, {{"a", "b", "c"}, false});
  });
  return 0;
}
