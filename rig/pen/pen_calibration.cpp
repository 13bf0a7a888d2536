#include "rig/pen/pen_calibration.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "rig/pen/pen_load.hpp"

namespace nibrig::rig::pen {
namespace {

// Samples older than this (or two windows) before the newest are dropped, but for the one the
// window starts under.
constexpr double kCalibrationKeepS = 5.0;

std::string pen_load_text(double newtons) {
  char text[64];
  std::snprintf(text, sizeof text, "%.3g N (%.0f g)", newtons, newtons / kStandardGravity * 1000.0);
  return text;
}

}  // namespace

PenCalibrator::PenCalibrator(PenCalibrationSettings settings) : settings_(settings) {
  if (!(settings_.window_s > 0.0) || !(settings_.steady_relative_sd > 0.0) ||
      !(settings_.steady_floor_sd >= 0.0) || settings_.min_samples < 1 ||
      !(settings_.same_load_relative >= 0.0))
    throw std::invalid_argument(
        "pen calibration: the window, the steadiness limits and the "
        "least sample count must be positive");
}

void PenCalibrator::add(const PenSample& sample) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (!sample.tip_down || !sample.in_proximity) {
    stroke_.clear();
    stroke_reports_ = 0;
    return;
  }
  if (!stroke_.empty() && !(sample.time_s > stroke_.back().time_s)) {
    // The same instant again (one evdev frame gives several events): the newer state wins.
    if (sample.time_s == stroke_.back().time_s) stroke_.back() = sample;
    return;
  }
  stroke_.push_back(sample);
  ++stroke_reports_;
  const double keep_s = std::max(kCalibrationKeepS, 2.0 * settings_.window_s);
  while (stroke_.size() > 2 && stroke_[1].time_s < sample.time_s - keep_s) stroke_.pop_front();
}

PenHoldCheck PenCalibrator::check(double now_s) const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return check_locked(now_s);
}

PenHoldCheck PenCalibrator::check_locked(double now_s) const {
  PenHoldCheck c;
  const double window = settings_.window_s;
  if (stroke_.empty()) {
    c.problem = "the pen's tip is up: press it on the scale and hold it steady";
    return c;
  }
  const double end = std::max(now_s, stroke_.back().time_s);
  const double start = end - window;
  char text[320];
  if (stroke_.front().time_s > start) {
    std::snprintf(text, sizeof text,
                  "the tip has been down for %.2f s: hold the load for at least %.2f s",
                  end - stroke_.front().time_s, window);
    c.problem = text;
    return c;
  }
  if (stroke_reports_ < settings_.min_samples) {
    std::snprintf(
        text, sizeof text,
        "the pen sent %zu reports since its tip went down, expected at least %zu (libinput "
        "reports only changes): too few to know the pressure; press again and hold",
        stroke_reports_, settings_.min_samples);
    c.problem = text;
    return c;
  }

  // Each report's pressure holds until the next one: a time-weighted mean and spread.
  double weight = 0.0, sum = 0.0, sum_sq = 0.0;
  for (std::size_t i = 0; i < stroke_.size(); ++i) {
    const double from = std::max(stroke_[i].time_s, start);
    const double to = std::min(i + 1 < stroke_.size() ? stroke_[i + 1].time_s : end, end);
    if (!(to > from)) continue;
    const double p = stroke_[i].pressure;
    weight += to - from;
    sum += p * (to - from);
    sum_sq += p * p * (to - from);
    ++c.samples;
  }
  c.pressure = sum / weight;
  c.pressure_sd = std::sqrt(std::max(0.0, sum_sq / weight - c.pressure * c.pressure));
  // A pen held by hand reports its pressure's tremor many times a second; a window with fewer
  // reports is a reader that fell behind or stopped, not a steady hold.
  if (c.samples < settings_.min_samples) {
    std::snprintf(text, sizeof text,
                  "the pen sent %zu reports over the last %.2f s, expected at least %zu: press Enter "
                  "again while holding (if it stays so, check the tablet)",
                  c.samples, window, settings_.min_samples);
    c.problem = text;
    return c;
  }
  if (!(c.pressure > 0.0)) {
    c.problem = "the pen reports no pressure: press harder, or check the pen has a pressure axis";
    return c;
  }
  const double limit =
      std::max(settings_.steady_relative_sd * c.pressure, settings_.steady_floor_sd);
  if (c.pressure_sd > limit) {
    std::snprintf(text, sizeof text,
                  "not steady: over the last %.2f s the pressure's standard deviation was %.4f "
                  "(%.1f %% of its mean %.4f), expected at most %.4f; hold the pen still",
                  window, c.pressure_sd, 100.0 * c.pressure_sd / c.pressure, c.pressure, limit);
    c.problem = text;
    return c;
  }
  c.ready = true;
  return c;
}

PenHold PenCalibrator::hold(double load_n, double now_s) {
  if (!std::isfinite(load_n) || !(load_n > 0.0) || load_n > kMaxPenForceN)
    throw std::invalid_argument("pen calibration: load " + std::to_string(load_n) +
                                " N: expected a force above 0 and at most " +
                                std::to_string(static_cast<int>(kMaxPenForceN)) + " N");
  const std::lock_guard<std::mutex> lock(mutex_);
  const PenHoldCheck c = check_locked(now_s);
  if (!c.ready)
    throw PenCalibrationRefusal("load " + pen_load_text(load_n) + " not taken: " + c.problem);
  PenHold h;
  h.force_n = load_n;
  h.pressure = c.pressure;
  h.pressure_sd = c.pressure_sd;
  h.samples = c.samples;
  holds_.push_back(h);
  return h;
}

std::vector<PenHold> PenCalibrator::holds() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return holds_;
}

void PenCalibrator::forget_last_hold() {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (!holds_.empty()) holds_.pop_back();
}

PressureCurve PenCalibrator::fit() const {
  std::vector<PenHold> sorted = holds();
  std::sort(sorted.begin(), sorted.end(),
            [](const PenHold& a, const PenHold& b) { return a.force_n < b.force_n; });
  // The same load held again: its pressures averaged.
  std::vector<PenHold> loads;
  std::vector<std::size_t> repeats;
  for (const PenHold& h : sorted) {
    if (!loads.empty() &&
        h.force_n - loads.back().force_n <= settings_.same_load_relative * h.force_n) {
      PenHold& merged = loads.back();
      const double n = static_cast<double>(++repeats.back());
      merged.pressure += (h.pressure - merged.pressure) / n;
      merged.force_n += (h.force_n - merged.force_n) / n;
      continue;
    }
    loads.push_back(h);
    repeats.push_back(1);
  }
  if (loads.size() < 3)
    throw PenCalibrationRefusal("a pen's curve needs at least 3 different loads, held " +
                                std::to_string(loads.size()) + ": hold more, light to heavy");
  std::vector<PressurePoint> points{{0.0, 0.0}};
  for (std::size_t i = 0; i < loads.size(); ++i) {
    if (i > 0 && !(loads[i].pressure > loads[i - 1].pressure)) {
      char text[300];
      std::snprintf(text, sizeof text,
                    "the pressure under %s (%.4f) is not above the pressure under %s (%.4f): "
                    "pressures must rise with load; hold %s again",
                    pen_load_text(loads[i].force_n).c_str(), loads[i].pressure,
                    pen_load_text(loads[i - 1].force_n).c_str(), loads[i - 1].pressure,
                    pen_load_text(loads[i].force_n).c_str());
      throw PenCalibrationRefusal(text);
    }
    points.push_back({loads[i].pressure, loads[i].force_n});
  }
  return PressureCurve(std::move(points));
}

}  // namespace nibrig::rig::pen
