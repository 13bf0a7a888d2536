// Stopping long model work from another thread (a window's Cancel button): the work takes a
// std::stop_token and throws Cancelled once it sees a stop requested, so that a cancelled job
// leaves no result behind, only the exception a caller recognises and does not show as an error.
#pragma once

#include <stdexcept>
#include <stop_token>
#include <string>

namespace nibrig::model::numeric {

class Cancelled : public std::runtime_error {
 public:
  explicit Cancelled(const std::string& what) : std::runtime_error(what + ": cancelled") {}
};

// `what` names the work in the exception ("bootstrap refits"). A default token never stops.
inline void throw_if_cancelled(const std::stop_token& stop, const std::string& what) {
  if (stop.stop_requested()) throw Cancelled(what);
}

}  // namespace nibrig::model::numeric
