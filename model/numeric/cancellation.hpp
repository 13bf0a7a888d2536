// Stopping long model work from another thread (a window's Cancel button): the flag a face sets and
// the exception the work throws once it has seen it, so that a cancelled job leaves no result
// behind, only the exception a face recognises and does not show as an error.
#pragma once

#include <atomic>
#include <stdexcept>
#include <string>

namespace nibrig::model::numeric {

// Set by the face, read by the work; nullptr: the work cannot be cancelled.
using CancelFlag = const std::atomic<bool>*;

class Cancelled : public std::runtime_error {
 public:
  explicit Cancelled(const std::string& what) : std::runtime_error(what + ": cancelled") {}
};

inline bool cancel_requested(CancelFlag cancel) {
  return cancel != nullptr && cancel->load(std::memory_order_relaxed);
}

// `what` names the work in the exception ("bootstrap refits").
inline void throw_if_cancelled(CancelFlag cancel, const std::string& what) {
  if (cancel_requested(cancel)) throw Cancelled(what);
}

}  // namespace nibrig::model::numeric
