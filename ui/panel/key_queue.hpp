// Key and character events from the window, handed to ImGui at most one change per key per frame.
// ImGui 1.86's GLFW back end keeps only whether a key is down when a frame starts, so a press and
// its release that arrive between two frames (a quick tap, an event-paced frame, a scripted key)
// left the key up and the press was lost: a participant's answer, Enter in a file dialog, Ctrl+1.
// ImGui 1.87 added such a queue of its own ("trickling" the inputs); this is that, for 1.86.
#pragma once

#include <cstddef>
#include <deque>
#include <functional>

namespace nibrig::ui::panel {

struct KeyEvent {
  enum class Kind { key, character };
  Kind kind = Kind::key;
  int key = 0, scancode = 0, action = 0, mods = 0;  // GLFW's, for Kind::key
  unsigned codepoint = 0;                           // for Kind::character
};

class KeyQueue {
 public:
  void push(const KeyEvent& event) { waiting_.push_back(event); }
  // Hands the waiting events to `sink` in the order they came, until one would change a key that
  // an event handed over in this call already changed (its release after its press, say): that
  // one and all after it wait for the next call, so that order is kept. Returns how many were
  // handed over. Call once per frame, before ImGui's NewFrame.
  std::size_t deliver(const std::function<void(const KeyEvent&)>& sink);
  // Events held for a later frame: the window should not sleep while there are any.
  std::size_t waiting() const { return waiting_.size(); }

 private:
  std::deque<KeyEvent> waiting_;
};

}  // namespace nibrig::ui::panel
