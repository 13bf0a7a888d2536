// Where the tip's speed (and normal force) comes from when nobody moves a real stylus: a constant, the rig's sweep
// (Sec. 4.3: 17 → 250 mm/s with a full period of 3 s) or an artist's recorded trajectory
// (../shared/data/piovarci2018/drawing). Evaluated on the audio thread: speed_at never allocates,
// locks or throws; everything that can fail happens at construction.
#pragma once

#include <vector>

#include "model/io/paper_drawing.hpp"
#include "rt/reference_load.hpp"

namespace nibrig::rt {

class SpeedSource {
 public:
  virtual ~SpeedSource() = default;
  // Tangential tip speed in m/s at time t (s) since the source started.
  virtual double speed_at(double t) const noexcept = 0;
  // Normal force in N at time t: the paper's load unless the source recorded one.
  virtual double force_at(double) const noexcept { return kReferenceNormalForce; }
};

class ConstantSpeed final : public SpeedSource {
 public:
  explicit ConstantSpeed(double speed_m_s);  // throws std::invalid_argument for a negative speed
  double speed_at(double) const noexcept override { return speed_; }

 private:
  double speed_;
};

// The paper gives the range and the period but not the shape; a triangle (up in half a period,
// down in the other half) is used because a sawtooth's jump from 250 back to 17 mm/s would itself
// be felt as an event. Starts at the low speed.
class SweepSpeed final : public SpeedSource {
 public:
  static constexpr double kPaperLow = 0.017, kPaperHigh = 0.250, kPaperPeriod = 3.0;
  explicit SweepSpeed(double low_m_s = kPaperLow, double high_m_s = kPaperHigh,
                      double period_s = kPaperPeriod);  // throws for low < 0, high < low, period ≤ 0
  double speed_at(double t) const noexcept override;

 private:
  double low_, high_, period_;
};

// A recorded trajectory replayed in a loop: speed and normal force interpolated linearly between
// frames (across a tracking dropout too), both 0 at frames where the pen did not touch. Throws
// std::invalid_argument for a trajectory with fewer than 2 frames or times that do not increase.
class TrajectorySpeed final : public SpeedSource {
 public:
  explicit TrajectorySpeed(const model::io::DrawingTrajectory& trajectory);
  double speed_at(double t) const noexcept override;
  double force_at(double t) const noexcept override;
  double duration() const noexcept { return time_.back(); }

 private:
  double interpolate(const std::vector<double>& values, double t) const noexcept;
  // Time from the first frame (s), speed (m/s), normal force (N).
  std::vector<double> time_, speed_, force_;
};

}  // namespace nibrig::rt
