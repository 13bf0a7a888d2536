#include "rig/speed_profile.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "model/io/format_error.hpp"
#include "model/io/text_lines.hpp"
#include "model/measure/step_segmentation.hpp"
#include "rt/stroke_source.hpp"

namespace nibrig::rig {
namespace {

std::string point_name(std::size_t i) { return "speed profile point " + std::to_string(i + 1); }

}  // namespace

SpeedProfile::SpeedProfile(std::string description, std::vector<ProfilePoint> points)
    : description_(std::move(description)), points_(std::move(points)) {
  if (points_.empty()) throw std::invalid_argument("a speed profile needs at least one point");
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const auto& p = points_[i];
    if (!std::isfinite(p.time_s) || !std::isfinite(p.speed_m_s))
      throw std::invalid_argument(point_name(i) + ": time and speed must be finite numbers");
    if (p.speed_m_s < 0.0)
      throw std::invalid_argument(point_name(i) + ": a negative speed (" +
                                  std::to_string(p.speed_m_s * 1e3) +
                                  " mm/s); the turntable turns one way");
    if (i == 0 && p.time_s != 0.0)
      throw std::invalid_argument(point_name(i) + ": the first point must be at time 0");
    if (i > 0 && p.time_s < points_[i - 1].time_s)
      throw std::invalid_argument(point_name(i) + ": time goes backwards (" +
                                  std::to_string(p.time_s) + " s after " +
                                  std::to_string(points_[i - 1].time_s) + " s)");
    if (p.time_s > kMaxProfileSeconds)
      throw std::invalid_argument(point_name(i) + ": at " + std::to_string(p.time_s) +
                                  " s, past the longest profile, " +
                                  std::to_string(static_cast<long>(kMaxProfileSeconds)) +
                                  " s (a day)");
    if (i > 1 && p.time_s == points_[i - 2].time_s)
      throw std::invalid_argument(point_name(i) +
                                  ": three points at one instant; a step is two points");
  }
}

double SpeedProfile::max_speed_m_s() const {
  double top = 0.0;
  for (const auto& p : points_) top = std::max(top, p.speed_m_s);
  return top;
}

double SpeedProfile::speed_at(double t) const {
  if (t < 0.0) return points_.front().speed_m_s;
  // The first breakpoint later than t: at a step (two points at one time) t == time takes the later.
  const auto after = std::upper_bound(points_.begin(), points_.end(), t,
                                      [](double x, const ProfilePoint& p) { return x < p.time_s; });
  if (after == points_.end()) return points_.back().speed_m_s;
  const auto& b = *after;
  const auto& a = *(after - 1);
  if (b.time_s == a.time_s) return b.speed_m_s;
  const double u = (t - a.time_s) / (b.time_s - a.time_s);
  return a.speed_m_s + u * (b.speed_m_s - a.speed_m_s);
}

void check_within_motor(const SpeedProfile& profile, double max_speed_m_s) {
  if (profile.max_speed_m_s() <= max_speed_m_s) return;
  char text[160];
  std::snprintf(text, sizeof text, "the profile asks for %.1f mm/s; the motor follows 0-%.0f mm/s",
                profile.max_speed_m_s() * 1e3, max_speed_m_s * 1e3);
  throw std::invalid_argument(text);
}

SpeedProfile fit_to_duration(const SpeedProfile& profile, double seconds) {
  if (!(seconds > 0.0) || !(seconds <= kMaxProfileSeconds))
    throw std::invalid_argument("a profile's length must be more than 0 and at most " +
                                std::to_string(static_cast<long>(kMaxProfileSeconds)) +
                                " s (a day), not " + std::to_string(seconds));
  const double period = profile.duration_s();
  if (period > 0.0 && seconds / period * static_cast<double>(profile.points().size()) >
                          static_cast<double>(kMaxProfilePoints))
    throw std::invalid_argument(
        "repeating a " + std::to_string(period) + " s profile of " +
        std::to_string(profile.points().size()) + " points for " + std::to_string(seconds) +
        " s would take more than " + std::to_string(kMaxProfilePoints) + " breakpoints");
  std::vector<ProfilePoint> points;
  if (period <= 0.0) {  // a constant speed
    points = {{0.0, profile.points().front().speed_m_s}, {seconds, profile.points().back().speed_m_s}};
    return SpeedProfile(profile.description(), std::move(points));
  }
  for (double start = 0.0; start < seconds; start += period) {
    for (const auto& p : profile.points()) {
      const double t = start + p.time_s;
      if (t > seconds) {
        if (points.back().time_s < seconds) points.push_back({seconds, profile.speed_at(seconds - start)});
        break;
      }
      // Where one repetition ends and the next begins at the same speed, one point suffices.
      if (!points.empty() && points.back().time_s == t && points.back().speed_m_s == p.speed_m_s)
        continue;
      points.push_back({t, p.speed_m_s});
    }
  }
  if (points.back().time_s < seconds) points.push_back({seconds, points.back().speed_m_s});
  return SpeedProfile(profile.description(), std::move(points));
}

SpeedProfile paper_steps(double seconds) {
  const model::measure::StepProtocol protocol;
  std::vector<ProfilePoint> sweep;
  double t = 0.0;
  sweep.push_back({0.0, 0.0});
  t += protocol.block_s * static_cast<double>(protocol.skipped_blocks_per_sweep);
  for (const double v : protocol.speeds_m_s) {
    sweep.push_back({t, sweep.back().speed_m_s});
    sweep.push_back({t, v});
    t += protocol.block_s;
  }
  sweep.push_back({t, sweep.back().speed_m_s});
  const std::string description = "paper steps: " + std::to_string(protocol.speeds_m_s.size()) +
                                  " speeds over 17-250 mm/s, " +
                                  std::to_string(static_cast<int>(protocol.block_s)) +
                                  " s each after " +
                                  std::to_string(static_cast<int>(protocol.block_s)) + " s at rest";
  SpeedProfile one(description, std::move(sweep));
  return seconds > 0.0 ? fit_to_duration(one, seconds) : one;
}

SpeedProfile study_sweep_profile(double seconds) {
  using rt::SweepStroke;
  const double half = SweepStroke::kPaperPeriod / 2.0;
  SpeedProfile one("sweep 17-250 mm/s, 3 s period",
                   {{0.0, SweepStroke::kPaperLow},
                    {half, SweepStroke::kPaperHigh},
                    {SweepStroke::kPaperPeriod, SweepStroke::kPaperLow}});
  return fit_to_duration(one, seconds);
}

SpeedProfile read_speed_profile(const std::filesystem::path& file) {
  model::io::TextLineReader reader(file);
  std::string line;
  std::vector<ProfilePoint> points;
  bool header = false;
  while (reader.next(line)) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    if (!header) {
      if (line.substr(first).rfind("time_s,speed_mm_s", 0) != 0)
        throw model::io::FormatError(file, model::io::line_place(reader.line_number()),
                                     "expected the header 'time_s,speed_mm_s'");
      header = true;
      continue;
    }
    const auto fields = model::io::split_fields(line);
    if (fields.size() != 2)
      throw model::io::FormatError(file, model::io::line_place(reader.line_number()),
                                   "expected two fields 'time_s,speed_mm_s', found " +
                                       std::to_string(fields.size()));
    const double time = model::io::parse_number(fields[0], file, reader.line_number(), "time_s");
    const double speed = model::io::parse_number(fields[1], file, reader.line_number(), "speed_mm_s");
    points.push_back({time, speed * 1e-3});
  }
  if (!header) throw model::io::FormatError(file, "", "empty: expected 'time_s,speed_mm_s' and rows");
  if (points.empty()) throw model::io::FormatError(file, "", "no rows after the header");
  try {
    return SpeedProfile("file " + file.filename().string(), std::move(points));
  } catch (const std::invalid_argument& e) {
    throw model::io::FormatError(file, "", e.what());
  }
}

}  // namespace nibrig::rig
