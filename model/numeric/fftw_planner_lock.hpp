// The one lock around FFTW's planner. FFTW's plan creation and destruction share global state and
// are not thread-safe (only fftw_execute* is), so every FFTW user (RealFft alone) takes this lock
// first.
#pragma once

#include <mutex>

namespace nibrig::model::numeric::detail {

std::mutex& fftw_planner_mutex();

}  // namespace nibrig::model::numeric::detail
