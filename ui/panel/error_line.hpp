// The panel's error line: the newest problem, shown whole (wrapped, scrolled past a few lines) until
// something succeeds, and the last few kept with the time they happened, to read after they have
// been cleared or replaced (Help > Errors).
#pragma once

#include <chrono>
#include <cstddef>
#include <deque>
#include <string>

namespace nibrig::ui::panel {

class ErrorLine {
 public:
  static constexpr std::size_t kKept = 50;
  struct Entry {
    std::chrono::system_clock::time_point when;
    std::string text;
  };

  // A new problem: shown, and kept (the same text twice in a row is kept once).
  void report(std::string text);
  // Something succeeded: the line empties; what was reported stays in the history.
  void clear() { current_.clear(); }
  const std::string& current() const { return current_; }
  const std::deque<Entry>& history() const { return history_; }

  // The line (nothing when empty), at most `max_lines` tall, then scrolled.
  void draw(int max_lines) const;
  // Its height as draw() will take it at `width`, to lay out what is above it.
  float height(float width, int max_lines) const;
  // The history, newest first, in a window of its own while `open`.
  void draw_history(bool* open) const;

 private:
  std::string current_;
  std::deque<Entry> history_;
};

}  // namespace nibrig::ui::panel
