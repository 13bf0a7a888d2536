// Progress on long work, drawn on stderr only when stderr is a terminal (quiet in pipes, CI and
// logs).
#pragma once

#include <cstddef>
#include <mutex>
#include <string>

namespace nibrig::ui::cli {

class Progress {
 public:
  Progress(std::string label, std::size_t total);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // Thread-safe: workers call this as each item finishes.
  void advance(const std::string& item);

 private:
  std::string label_;
  std::size_t total_;
  std::size_t done_ = 0;
  bool enabled_;
  std::mutex mutex_;
};

}  // namespace nibrig::ui::cli
