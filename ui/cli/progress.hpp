// Progress on long work, drawn on stderr only when stderr is a terminal (quiet in pipes, CI and
// logs).
#pragma once

#include <cstddef>
#include <functional>
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

// A model progress callback (model::numeric::Progress: done, total) that draws a Progress bar
// labelled `label`: the bar appears with the first unit, when the total is known, and ends its
// line with the last. Copies share one bar.
std::function<void(std::size_t done, std::size_t total)> progress_bar(std::string label);

}  // namespace nibrig::ui::cli
