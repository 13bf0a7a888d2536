// One time base for two clocks: a device stamps what it sends with its own clock (the rig
// controller's microsecond counter, an audio interface's sample count), the host notes when each
// stamp arrives on its steady clock. Arrival = true time + a latency that is never below some
// minimum and often above it (USB polling, scheduling, audio periods), so the earliest arrivals are
// the truest: per window of device time the pair with the smallest host - device offset is kept,
// and a least-squares line through those minima maps device time to host time — its slope is the
// device clock's drift. The residual of the minima about the line says how well the mapping holds;
// the capture reports it as part of its alignment error.
#pragma once

#include <cstddef>
#include <deque>

namespace nibrig::rig {

class ClockFit {
 public:
  // Windows of `window_s` device seconds; the newest `max_windows` are fitted, so a drift that
  // itself changes (a crystal warming up) is followed. Throws std::invalid_argument for window_s
  // <= 0 or max_windows < 2.
  explicit ClockFit(double window_s = 0.25, std::size_t max_windows = 240);

  // A stamp `device_s` (device seconds) that arrived at `host_s` (host seconds). Stamps must not go
  // backwards in device time (an older one is ignored).
  void add(double device_s, double host_s);

  // At least two windows with a minimum: the line is defined.
  bool ready() const { return minima_.size() >= 2; }
  std::size_t windows() const { return minima_.size(); }
  // Host time of device time `device_s` (ready() only; otherwise the newest offset, or device_s).
  double host_time(double device_s) const;
  // The inverse: the device time that maps to `host_s`.
  double device_time(double host_s) const;
  // (device rate − host rate) / host rate, in parts per million: positive when the device's clock
  // runs fast.
  double drift_ppm() const;
  // RMS distance of the windows' minima from the line, in seconds.
  double residual_s() const;

 private:
  struct Minimum {
    double device_s, offset_s;  // offset = host − device
  };
  void refit();

  double window_s_;
  std::size_t max_windows_;
  std::deque<Minimum> minima_;  // closed windows, oldest first
  bool open_ = false;           // a window is being filled
  Minimum current_{};           // its minimum so far
  double window_start_ = 0.0;
  double last_device_ = -1e300;
  // offset = intercept + slope · (device − reference)
  double reference_ = 0.0, intercept_ = 0.0, slope_ = 0.0, residual_ = 0.0;
};

}  // namespace nibrig::rig
