// Measuring a pen's pressure curve (`nibrig pen calibrate`): the pen pressed on a kitchen scale, or
// on the rig's force sensor, at a few loads; at each the user says the load it reads, and the mean
// pressure over the last steady half second is taken. Three loads or more give the curve.
#pragma once

#include <cstddef>
#include <deque>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "rig/pen/pen_force.hpp"
#include "rig/pen/pen_force_file.hpp"
#include "rig/pen/pen_sample.hpp"

namespace nibrig::rig::pen {

// Why a hold or a fit was refused; the message says what to do.
class PenCalibrationRefusal : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct PenCalibrationSettings {
  double window_s = 0.5;  // the hold averaged: long enough to average a hand's tremor
  // Steady: the pressure's standard deviation over the window at most this share of its mean…
  double steady_relative_sd = 0.05;
  // …or at most this, in normalised pressure: two levels of a 1024-level pen, so that a light hold
  // is not refused for its quantisation alone.
  double steady_floor_sd = 0.002;
  // Reports since the tip went down, at least. libinput reports a change only, so a still pen may
  // send few; fewer than this in a hold of window_s and the hold is not known well enough.
  std::size_t min_samples = 5;
  // Two loads within this share of each other are the same load held again: their pressures are
  // averaged.
  double same_load_relative = 0.01;
};

// The last window as it stands: what a face shows while the user settles the load, and what a hold
// takes.
struct PenHoldCheck {
  bool ready = false;                        // a hold now would be taken
  std::string problem;                       // why not, when not ready: what to do
  double pressure = 0.0, pressure_sd = 0.0;  // over the window, once the tip has been down for it
  std::size_t samples = 0;                   // reports in the window
};

// Every call may come from any thread: the pen reader's calls add, a face's the rest.
class PenCalibrator {
 public:
  explicit PenCalibrator(PenCalibrationSettings settings = {});

  // Every sample from the pen's reader, in order.
  void add(const PenSample& sample);

  // The pressure's mean and spread over [now − window, now] (`now_s` on the samples' clock, e.g.
  // pen_clock_now_s()), each report's pressure held until the next (libinput reports changes
  // only). Not ready when the tip is up or out of proximity, when it has been down for less than
  // the window or sent fewer than min_samples reports since, when the pressure in the window is 0,
  // or when it is not steady (the problem gives the spread and the limit).
  PenHoldCheck check(double now_s) const;

  // The pen holds `load_n` newtons now: check(now_s)'s mean, kept. Throws PenCalibrationRefusal
  // with the load and check's problem when it is not ready; std::invalid_argument for a load that
  // is not a force a pen takes.
  PenHold hold(double load_n, double now_s);

  std::vector<PenHold> holds() const;
  void forget_last_hold();

  // The curve through the holds: a point at (0, 0 N) — libinput's pressure 0 is where the tip
  // starts to bear load, a few grams — then each load's pressure, the same load held again
  // averaged. Throws PenCalibrationRefusal for fewer than three distinct loads, or naming the
  // first load whose pressure is not above the next lighter load's.
  PressureCurve fit() const;

 private:
  PenHoldCheck check_locked(double now_s) const;

  const PenCalibrationSettings settings_;
  mutable std::mutex mutex_;
  std::deque<PenSample> stroke_;  // since the tip went down (the oldest trimmed)
  std::size_t stroke_reports_ = 0;
  std::vector<PenHold> holds_;
};

}  // namespace nibrig::rig::pen
