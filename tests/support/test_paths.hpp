// Where tests find the shared real data and a scratch folder of their own.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace nibrig::test {

// ../shared/data beside the repository, or $NIBRIG_SHARED_DATA. Tests of the science use real
// recordings; a missing folder is a failure, not a skip.
std::filesystem::path shared_data();

// A fresh, empty folder under the build tree for one test process (removed and recreated on each
// call with the same name in the same process).
std::filesystem::path scratch_dir(const std::string& name);

// The repository's assets/ folder.
std::filesystem::path assets_dir();

// The entries of a folder, in the order the file system lists them; none when it does not exist.
std::vector<std::filesystem::path> files_in(const std::filesystem::path& dir);

// NIBRIG_CACHE pointed at `dir` for one scope, and put back as it was after it: the user cache of
// what a test computes is its own.
class ScopedCacheDir {
 public:
  explicit ScopedCacheDir(std::filesystem::path dir);
  ~ScopedCacheDir();
  ScopedCacheDir(const ScopedCacheDir&) = delete;
  ScopedCacheDir& operator=(const ScopedCacheDir&) = delete;

 private:
  std::optional<std::string> old_;
};

// An environment variable set for one scope and put back as it was after it: a lab's own store
// (NIBRIG_MATERIALS, NIBRIG_PRINTERS) pointed at a test's scratch folder.
class ScopedEnvironment {
 public:
  ScopedEnvironment(std::string name, const std::string& value);
  ~ScopedEnvironment();
  ScopedEnvironment(const ScopedEnvironment&) = delete;
  ScopedEnvironment& operator=(const ScopedEnvironment&) = delete;

 private:
  std::string name_;
  std::optional<std::string> old_;
};

}  // namespace nibrig::test
