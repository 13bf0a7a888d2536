// The pen's speed over the tablet, from the positions libinput reports at the tablet's own rate:
// the speed the engine's live contact takes while a pen stroke lasts. Not thread-safe: one thread
// feeds and asks (pen_contact.hpp guards it).
#pragma once

#include <array>
#include <cstddef>

namespace nibrig::rig::pen {

class PenSpeed {
 public:
  // The distance between the newest position and the one two reports before, over their time: a
  // central difference, exact for a steady acceleration at the middle report, so its lag is one
  // report. It halves the stamp jitter's and the quantisation's share of a one-report difference;
  // a longer centred window would lag by more than one report.
  static constexpr double kLagReports = 1.0;
  // libinput sends nothing while no axis changes: after this many report intervals without a
  // report the pen counts as held still (speed 0). Two would stop a slow pen that moves one
  // resolution step every other report whenever that report comes late by the stamp jitter.
  static constexpr double kStillIntervals = 2.5;
  // The interval assumed until enough are measured: 133 Hz, Wacom Intuos's report rate.
  static constexpr double kAssumedIntervalS = 1.0 / 133.0;
  // Intervals outside 2-50 ms (500-20 Hz) are a pause or a broken stamp, not the tablet's rate:
  // they are not measured.
  static constexpr double kShortestIntervalS = 0.002, kLongestIntervalS = 0.050;

  // A new stroke: the positions are forgotten (the next report gives speed 0), the measured report
  // interval is kept (it is the tablet's, not the stroke's).
  void reset();

  // One report: kernel time (s, CLOCK_MONOTONIC) and position (m). Returns the speed after it, in
  // m/s. A report whose stamp is not later than the previous one is skipped (counted in
  // skipped()), as is one with a coordinate that is not finite: no interval is ever zero or
  // negative. After a gap longer than the still timeout the window starts again at the gap's
  // start: the speed is the mean over the gap, whether the pen paused (it then rises from low, as a
  // pen setting off does) or reports were lost. Taking the pen to have left one report before the
  // new one instead gave three times the speed on the paper's artists' strokes, whose tracker loses
  // frames.
  double add(double time_s, double x_m, double y_m);

  // The newest estimate, or 0 when no report came for still_timeout_s() before `now_s` (the same
  // clock as the reports): what a caller's periodic tick posts while the pen is held still.
  double speed_at(double now_s) const;
  double speed() const noexcept { return speed_; }

  // The median of the last intervals between successive reports within strokes (those outside
  // 2-50 ms left out), kAssumedIntervalS until four are measured. The median holds
  // through the reports libinput leaves out when nothing changed, as long as most carry a change.
  double report_interval_s() const noexcept { return interval_s_; }
  std::size_t intervals_measured() const noexcept { return intervals_seen_; }
  // The lag the smoothing adds, in seconds at the measured rate.
  double lag_s() const noexcept { return kLagReports * interval_s_; }
  double still_timeout_s() const noexcept;
  std::size_t skipped() const noexcept { return skipped_; }

 private:
  struct Report {
    double time_s, x_m, y_m;
  };
  void measure_interval(double interval_s);

  // The last three reports of the stroke, newest at [count_ - 1].
  std::array<Report, 3> window_{};
  std::size_t count_ = 0;
  double speed_ = 0.0;
  double last_time_s_ = 0.0;
  bool any_report_ = false;

  static constexpr std::size_t kIntervalHistory = 64;
  std::array<double, kIntervalHistory> intervals_{};
  std::size_t intervals_seen_ = 0;
  double interval_s_ = kAssumedIntervalS;
  std::size_t skipped_ = 0;
};

}  // namespace nibrig::rig::pen
