#include "rt/speed_source.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace nibrig::rt {

ConstantSpeed::ConstantSpeed(double speed_m_s) : speed_(speed_m_s) {
  if (!(speed_m_s >= 0) || !std::isfinite(speed_m_s))
    throw std::invalid_argument("a constant speed must be finite and not negative");
}

SweepSpeed::SweepSpeed(double low_m_s, double high_m_s, double period_s)
    : low_(low_m_s), high_(high_m_s), period_(period_s) {
  if (!(low_m_s >= 0) || !(high_m_s >= low_m_s) || !std::isfinite(high_m_s))
    throw std::invalid_argument("a sweep needs 0 <= low <= high speed");
  if (!(period_s > 0) || !std::isfinite(period_s))
    throw std::invalid_argument("a sweep needs a positive period");
}

double SweepSpeed::speed_at(double t) const noexcept {
  const double phase = t / period_ - std::floor(t / period_);  // [0, 1)
  const double rise = phase < 0.5 ? 2.0 * phase : 2.0 * (1.0 - phase);
  return low_ + (high_ - low_) * rise;
}

TrajectorySpeed::TrajectorySpeed(const model::io::DrawingTrajectory& trajectory) {
  const auto& t = trajectory.time_s;
  if (t.size() < 2 || trajectory.speed_m_s.size() != t.size() ||
      trajectory.touching.size() != t.size() || trajectory.normal_force_N.size() != t.size())
    throw std::invalid_argument(trajectory.source.string() +
                                ": a trajectory needs at least 2 frames with speed and touch");
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (i > 0 && !(t[i] > t[i - 1]))
      throw std::invalid_argument(trajectory.source.string() + ": frame " + std::to_string(i) +
                                  " does not come after the one before it");
    time_.push_back(t[i] - t.front());
    const bool touching = trajectory.touching[i];
    speed_.push_back(touching ? std::max(0.0, trajectory.speed_m_s[i]) : 0.0);
    // The tracker reports small negative forces (sensor offset) while touching: no pull, so 0.
    force_.push_back(touching ? std::max(0.0, trajectory.normal_force_N[i]) : 0.0);
  }
}

double TrajectorySpeed::speed_at(double t) const noexcept { return interpolate(speed_, t); }
double TrajectorySpeed::force_at(double t) const noexcept { return interpolate(force_, t); }

double TrajectorySpeed::interpolate(const std::vector<double>& values, double t) const noexcept {
  const double wrapped = t - duration() * std::floor(t / duration());
  const auto after = std::upper_bound(time_.begin(), time_.end(), wrapped);
  if (after == time_.end()) return values.back();
  const auto i = static_cast<std::size_t>(after - time_.begin());
  if (i == 0) return values.front();
  const double f = (wrapped - time_[i - 1]) / (time_[i] - time_[i - 1]);
  return values[i - 1] + f * (values[i] - values[i - 1]);
}

}  // namespace nibrig::rt
