#include "model/measure/fftw_planner_lock.hpp"

namespace nibrig::model::measure::detail {

std::mutex& fftw_planner_mutex() {
  // A function-local static: constructed on first use, so it exists before any static analyzer.
  static std::mutex mutex;
  return mutex;
}

}  // namespace nibrig::model::measure::detail
