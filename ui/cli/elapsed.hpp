// Wall time since a moment, in seconds: what the commands report about their own stages.
#pragma once

#include <chrono>

namespace nibrig::ui::cli {

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace nibrig::ui::cli
