#include "ui/panel/key_queue.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <vector>

namespace nibrig::ui::panel {

std::size_t KeyQueue::deliver(const std::function<void(const KeyEvent&)>& sink) {
  std::vector<int> changed;  // keys pressed or released in this call
  std::size_t handed = 0;
  while (!waiting_.empty()) {
    const KeyEvent& event = waiting_.front();
    // A held key's repeats change nothing ImGui 1.86 keeps; presses and releases change its state.
    const bool changes = event.kind == KeyEvent::Kind::key && event.action != GLFW_REPEAT;
    if (changes && std::find(changed.begin(), changed.end(), event.key) != changed.end()) break;
    if (changes) changed.push_back(event.key);
    sink(event);
    waiting_.pop_front();
    ++handed;
  }
  return handed;
}

}  // namespace nibrig::ui::panel
