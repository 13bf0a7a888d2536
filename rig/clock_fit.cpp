#include "rig/clock_fit.hpp"

#include <cmath>
#include <stdexcept>

namespace nibrig::rig {

ClockFit::ClockFit(double window_s, std::size_t max_windows)
    : window_s_(window_s), max_windows_(max_windows) {
  if (!(window_s > 0.0) || !std::isfinite(window_s))
    throw std::invalid_argument("clock fit: the window must be a positive number of seconds");
  if (max_windows < 2) throw std::invalid_argument("clock fit: a line needs at least 2 windows");
}

void ClockFit::add(double device_s, double host_s) {
  if (device_s < last_device_ || !std::isfinite(device_s) || !std::isfinite(host_s)) return;
  last_device_ = device_s;
  const double offset = host_s - device_s;
  if (open_ && device_s >= window_start_ + window_s_) {
    // The window is closed: its minimum joins the fit.
    minima_.push_back(current_);
    if (minima_.size() > max_windows_) minima_.pop_front();
    open_ = false;
    refit();
  }
  if (!open_) {
    open_ = true;
    window_start_ = device_s;
    current_ = {device_s, offset};
  } else if (offset < current_.offset_s) {
    current_ = {device_s, offset};
  }
}

void ClockFit::refit() {
  const double n = static_cast<double>(minima_.size());
  if (minima_.size() < 2) {
    intercept_ = minima_.empty() ? 0.0 : minima_.back().offset_s;
    slope_ = 0.0;
    residual_ = 0.0;
    return;
  }
  // Centred on the mean device time so that the sums stay well conditioned over hours.
  double mean_x = 0.0, mean_y = 0.0;
  for (const auto& m : minima_) mean_x += m.device_s, mean_y += m.offset_s;
  mean_x /= n, mean_y /= n;
  double sxx = 0.0, sxy = 0.0;
  for (const auto& m : minima_) {
    const double dx = m.device_s - mean_x;
    sxx += dx * dx;
    sxy += dx * (m.offset_s - mean_y);
  }
  reference_ = mean_x;
  slope_ = sxx > 0.0 ? sxy / sxx : 0.0;
  intercept_ = mean_y;
  double sum = 0.0;
  for (const auto& m : minima_) {
    const double r = m.offset_s - (intercept_ + slope_ * (m.device_s - reference_));
    sum += r * r;
  }
  residual_ = std::sqrt(sum / n);
}

double ClockFit::host_time(double device_s) const {
  if (minima_.empty()) return open_ ? device_s + current_.offset_s : device_s;
  return device_s + intercept_ + slope_ * (device_s - reference_);
}

// host = device + intercept + slope·(device − reference), solved for device.
double ClockFit::device_time(double host_s) const {
  if (minima_.empty()) return open_ ? host_s - current_.offset_s : host_s;
  return (host_s - intercept_ + slope_ * reference_) / (1.0 + slope_);
}

// host = device·(1 + slope) + c, so the device's clock runs at 1 / (1 + slope) of the host's.
double ClockFit::drift_ppm() const { return 1e6 * (1.0 / (1.0 + slope_) - 1.0); }

double ClockFit::residual_s() const { return residual_; }

}  // namespace nibrig::rig
