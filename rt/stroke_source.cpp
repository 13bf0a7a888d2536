#include "rt/stroke_source.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace nibrig::rt {
namespace {

void check_force(double force_n) {
  if (!(force_n >= 0) || !std::isfinite(force_n))
    throw std::invalid_argument("a stroke's normal force must be finite and not negative");
}

}  // namespace

ConstantStroke::ConstantStroke(double speed_m_s, double force_n) : speed_(speed_m_s), force_(force_n) {
  if (!(speed_m_s >= 0) || !std::isfinite(speed_m_s))
    throw std::invalid_argument("a constant speed must be finite and not negative");
  check_force(force_n);
}

void ConstantStroke::fill(std::uint64_t, double, double* speed, double* force,
                          std::size_t count) noexcept {
  std::fill_n(speed, count, speed_);
  std::fill_n(force, count, force_);
}

SweepStroke::SweepStroke(double low_m_s, double high_m_s, double period_s, double force_n)
    : low_(low_m_s), high_(high_m_s), period_(period_s), force_(force_n) {
  if (!(low_m_s >= 0) || !(high_m_s >= low_m_s) || !std::isfinite(high_m_s))
    throw std::invalid_argument("a sweep needs 0 <= low <= high speed");
  if (!(period_s > 0) || !std::isfinite(period_s))
    throw std::invalid_argument("a sweep needs a positive period");
  check_force(force_n);
}

double SweepStroke::speed_at(double t) const noexcept {
  const double phase = t / period_ - std::floor(t / period_);  // [0, 1)
  const double rise = phase < 0.5 ? 2.0 * phase : 2.0 * (1.0 - phase);
  return low_ + (high_ - low_) * rise;
}

void SweepStroke::fill(std::uint64_t first, double rate, double* speed, double* force,
                       std::size_t count) noexcept {
  for (std::size_t i = 0; i < count; ++i) speed[i] = speed_at(static_cast<double>(first + i) / rate);
  std::fill_n(force, count, force_);
}

TrajectoryStroke::TrajectoryStroke(const model::io::DrawingTrajectory& trajectory) {
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

TrajectoryStroke::TrajectoryStroke(const model::io::DrawingTrajectory& trajectory, double force_n)
    : TrajectoryStroke(trajectory) {
  check_force(force_n);
  // As asked, everywhere: where the pen lifted the speed is 0 and the forcing silent anyway.
  std::fill(force_.begin(), force_.end(), force_n);
}

TrajectoryStroke::Place TrajectoryStroke::locate(double t) const noexcept {
  const double wrapped = t - duration() * std::floor(t / duration());
  const auto after = std::upper_bound(time_.begin(), time_.end(), wrapped);
  if (after == time_.end()) return {time_.size() - 1, 0.0};
  const auto i = static_cast<std::size_t>(after - time_.begin());
  if (i == 0) return {0, 0.0};
  return {i - 1, (wrapped - time_[i - 1]) / (time_[i] - time_[i - 1])};
}

double TrajectoryStroke::blend(const std::vector<double>& values, Place p) noexcept {
  if (p.fraction == 0.0) return values[p.before];
  return values[p.before] + p.fraction * (values[p.before + 1] - values[p.before]);
}

void TrajectoryStroke::fill(std::uint64_t first, double rate, double* speed, double* force,
                            std::size_t count) noexcept {
  for (std::size_t n = 0; n < count; ++n) {
    const Place p = locate(static_cast<double>(first + n) / rate);  // one search for both
    speed[n] = blend(speed_, p);
    force[n] = blend(force_, p);
  }
}

void LiveStroke::fill(std::uint64_t, double, double* speed, double* force, std::size_t count) noexcept {
  for (std::size_t i = 0; i < count; ++i) {
    const double u = static_cast<double>(i + 1) / static_cast<double>(count);
    speed[i] = speed_ + u * (target_speed_ - speed_);
    force[i] = force_ + u * (target_force_ - force_);
  }
  if (count > 0) {
    speed_ = target_speed_;
    force_ = target_force_;
  }
}

}  // namespace nibrig::rt
