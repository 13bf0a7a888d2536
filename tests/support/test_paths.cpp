#include "tests/support/test_paths.hpp"

#include <unistd.h>

#include <cstdlib>
#include <stdexcept>

namespace nibrig::test {

std::filesystem::path shared_data() {
  const char* env = std::getenv("NIBRIG_SHARED_DATA");
  std::filesystem::path dir = env != nullptr ? env : NIBRIG_SHARED_DATA_DEFAULT;
  if (!std::filesystem::is_directory(dir)) {
    throw std::runtime_error("shared data folder not found: " + dir.string() +
                             " (set NIBRIG_SHARED_DATA or place shared/ beside the repository)");
  }
  return dir;
}

std::filesystem::path scratch_dir(const std::string& name) {
  // ctest runs tests in parallel, each in its own process: the process id keeps two tests that
  // chose the same name from removing each other's files.
  std::filesystem::path dir = std::filesystem::path(NIBRIG_TEST_BINARY_DIR) / "scratch" /
                              (name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::filesystem::path assets_dir() { return std::filesystem::path(NIBRIG_SOURCE_DIR) / "assets"; }

std::vector<std::filesystem::path> files_in(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> out;
  if (!std::filesystem::exists(dir)) return out;
  for (const auto& e : std::filesystem::directory_iterator(dir)) out.push_back(e.path());
  return out;
}

ScopedCacheDir::ScopedCacheDir(std::filesystem::path dir) {
  if (const char* old = std::getenv("NIBRIG_CACHE")) old_ = old;
  ::setenv("NIBRIG_CACHE", dir.c_str(), 1);
}

ScopedCacheDir::~ScopedCacheDir() {
  if (old_)
    ::setenv("NIBRIG_CACHE", old_->c_str(), 1);
  else
    ::unsetenv("NIBRIG_CACHE");
}

ScopedEnvironment::ScopedEnvironment(std::string name, const std::string& value) : name_(std::move(name)) {
  if (const char* old = std::getenv(name_.c_str())) old_ = old;
  ::setenv(name_.c_str(), value.c_str(), 1);
}

ScopedEnvironment::~ScopedEnvironment() {
  if (old_)
    ::setenv(name_.c_str(), old_->c_str(), 1);
  else
    ::unsetenv(name_.c_str());
}

}  // namespace nibrig::test
