#include "model/numeric/fftw_planner_lock.hpp"

namespace nibrig::model::numeric::detail {

std::mutex& fftw_planner_mutex() {
  // A function-local static: constructed on first use, so it exists before any static analyzer.
  static std::mutex mutex;
  return mutex;
}

}  // namespace nibrig::model::numeric::detail
