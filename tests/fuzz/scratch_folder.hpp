// A fresh scratch folder per fuzz input for the libFuzzer targets in tests/fuzz: the readers under
// test take paths, so each input is written to files in a folder of its own.
#pragma once

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>

namespace nibrig::test {

// A fresh folder for one input, removed afterwards; mkdtemp keeps parallel jobs (-jobs=N) apart.
// Per input rather than per process because libFuzzer ends with _Exit, which skips any cleanup
// registered for exit. In memory when possible: rewriting files on ext4 flushes them to disk on
// close, which slows fuzzing ~50x.
class ScratchFolder {
 public:
  // The folder is named <prefix>-XXXXXX, the X's filled in by mkdtemp.
  explicit ScratchFolder(std::string_view prefix) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path base = std::getenv("TMPDIR") == nullptr && fs::is_directory("/dev/shm", ec)
                              ? fs::path("/dev/shm")
                              : fs::temp_directory_path();
    std::string pattern = (base / (std::string(prefix) + "-XXXXXX")).string();
    if (::mkdtemp(pattern.data()) == nullptr) std::abort();  // the harness failed, not a reader
    path_ = pattern;
  }
  ~ScratchFolder() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace nibrig::test
