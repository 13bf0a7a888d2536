#include "rig/pen/pen_speed.hpp"

#include <algorithm>
#include <cmath>

namespace nibrig::rig::pen {

void PenSpeed::reset() {
  count_ = 0;
  speed_ = 0.0;
}

double PenSpeed::still_timeout_s() const noexcept { return kStillIntervals * interval_s_; }

void PenSpeed::measure_interval(double interval_s) {
  if (interval_s < kShortestIntervalS || interval_s > kLongestIntervalS) return;
  intervals_[intervals_seen_ % kIntervalHistory] = interval_s;
  ++intervals_seen_;
  if (intervals_seen_ < 4) return;
  const std::size_t n = std::min(intervals_seen_, kIntervalHistory);
  std::array<double, kIntervalHistory> sorted = intervals_;
  const auto middle = sorted.begin() + static_cast<std::ptrdiff_t>(n / 2);
  std::nth_element(sorted.begin(), middle, sorted.begin() + static_cast<std::ptrdiff_t>(n));
  interval_s_ = *middle;
}

double PenSpeed::add(double time_s, double x_m, double y_m) {
  if (!std::isfinite(time_s) || !std::isfinite(x_m) || !std::isfinite(y_m) ||
      (any_report_ && !(time_s > last_time_s_))) {
    ++skipped_;
    return speed_;
  }
  if (count_ > 0) {
    const Report& last = window_[count_ - 1];
    const double gap_s = time_s - last.time_s;
    // The timeout as it stood while the gap lasted, as speed_at judged it.
    const bool restart = gap_s > still_timeout_s();
    measure_interval(gap_s);
    if (restart) {
      // Across a pause or lost reports only the gap itself is known: the window starts again at
      // its start.
      window_[0] = last;
      count_ = 1;
    }
  }
  if (count_ == window_.size()) {
    window_[0] = window_[1];
    window_[1] = window_[2];
    --count_;
  }
  window_[count_++] = {time_s, x_m, y_m};
  any_report_ = true;
  last_time_s_ = time_s;

  if (count_ < 2) {
    speed_ = 0.0;
  } else {
    const Report& from = window_[0];
    const Report& to = window_[count_ - 1];
    speed_ = std::hypot(to.x_m - from.x_m, to.y_m - from.y_m) / (to.time_s - from.time_s);
  }
  return speed_;
}

double PenSpeed::speed_at(double now_s) const {
  if (count_ == 0) return 0.0;
  if (now_s - window_[count_ - 1].time_s > still_timeout_s()) return 0.0;
  return speed_;
}

}  // namespace nibrig::rig::pen
