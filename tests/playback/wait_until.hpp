// Polling with a deadline for the playback tests, which wait on real servers and threads.
#pragma once

#include <chrono>
#include <thread>

namespace nibrig::playback::testing {

// Polls `done` every 5 ms; returns how long it took, or a negative duration when `timeout`
// passed first.
template <typename Predicate>
std::chrono::duration<double> wait_until(Predicate done, std::chrono::duration<double> timeout) {
  const auto start = std::chrono::steady_clock::now();
  while (!done()) {
    if (std::chrono::steady_clock::now() - start > timeout)
      return std::chrono::duration<double>(-1);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return std::chrono::steady_clock::now() - start;
}

}  // namespace nibrig::playback::testing
