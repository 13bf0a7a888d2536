// Where the tip's speed and normal force come from, one block at a time: a constant, the rig's
// sweep (Sec. 4.3: 17 → 250 mm/s with a full period of 3 s), an artist's recorded trajectory
// (../shared/data/piovarci2018/drawing), or a live contact (a stylus, the pad, the turntable).
// Recorded and live strokes are the same kind of thing to the engine: it asks for a block of
// samples once per block, on the audio thread, so fill() never allocates, locks or throws;
// everything that can fail happens at construction (ARCHITECTURE.md, "Real-time rules").
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "model/io/paper_drawing.hpp"
#include "rt/reference_load.hpp"

namespace nibrig::rt {

class StrokeSource {
 public:
  virtual ~StrokeSource() = default;
  // Tangential tip speed (m/s) and normal force (N) at the `count` samples first, first + 1, …
  // of the source's own clock, which ticks `rate` times a second from 0 when the engine takes
  // the source over. Sample n is at time n / rate exactly, so a render and a device agree.
  virtual void fill(std::uint64_t first, double rate, double* speed, double* force,
                    std::size_t count) noexcept = 0;
};

class ConstantStroke final : public StrokeSource {
 public:
  // Throws std::invalid_argument for a negative or non-finite speed or force.
  explicit ConstantStroke(double speed_m_s, double force_n = kReferenceNormalForce);
  void fill(std::uint64_t, double, double* speed, double* force, std::size_t count) noexcept override;

 private:
  double speed_, force_;
};

// The paper gives the range and the period but not the shape; a triangle (up in half a period,
// down in the other half) is used because a sawtooth's jump from 250 back to 17 mm/s would itself
// be felt as an event. Starts at the low speed; the force is constant.
class SweepStroke final : public StrokeSource {
 public:
  static constexpr double kPaperLow = 0.017, kPaperHigh = 0.250, kPaperPeriod = 3.0;
  // Throws for low < 0, high < low, period ≤ 0, a negative force, or anything not finite.
  explicit SweepStroke(double low_m_s = kPaperLow, double high_m_s = kPaperHigh,
                       double period_s = kPaperPeriod, double force_n = kReferenceNormalForce);
  double speed_at(double t) const noexcept;
  void fill(std::uint64_t first, double rate, double* speed, double* force,
            std::size_t count) noexcept override;

 private:
  double low_, high_, period_, force_;
};

// A recorded trajectory replayed in a loop: speed and normal force interpolated linearly between
// frames (across a tracking dropout too), both 0 at frames where the pen did not touch. The
// recorded force can be replaced by a constant one. Throws std::invalid_argument for a trajectory
// with fewer than 2 frames, times that do not increase, or a bad force.
class TrajectoryStroke final : public StrokeSource {
 public:
  explicit TrajectoryStroke(const model::io::DrawingTrajectory& trajectory);
  TrajectoryStroke(const model::io::DrawingTrajectory& trajectory, double force_n);
  double speed_at(double t) const noexcept { return blend(speed_, locate(t)); }
  double force_at(double t) const noexcept { return blend(force_, locate(t)); }
  double duration() const noexcept { return time_.back(); }
  void fill(std::uint64_t first, double rate, double* speed, double* force,
            std::size_t count) noexcept override;

 private:
  struct Place {
    std::size_t before;  // the frame at or before the time (wrapped into the loop)
    double fraction;     // of the way to the next frame; 0 at or past the last frame
  };
  Place locate(double t) const noexcept;
  static double blend(const std::vector<double>& values, Place p) noexcept;
  // Time from the first frame (s), speed (m/s), normal force (N).
  std::vector<double> time_, speed_, force_;
};

// A live contact: a control thread posts the newest speed and force; each block ramps linearly
// from the value reached to the newest over its samples, so a value acts within one block and
// never as a step. The engine owns one and reads its posts from its own queue; the rig and the pad
// post through Engine::set_contact.
class LiveStroke final : public StrokeSource {
 public:
  // Audio side: the newest posted value, and where the ramp starts (a handover from another source).
  void aim(double speed_m_s, double force_n) noexcept { target_speed_ = speed_m_s, target_force_ = force_n; }
  void start_from(double speed_m_s, double force_n) noexcept { speed_ = speed_m_s, force_ = force_n; }
  void fill(std::uint64_t, double, double* speed, double* force, std::size_t count) noexcept override;

 private:
  double speed_ = 0, force_ = 0;                // reached at the end of the last block
  double target_speed_ = 0, target_force_ = 0;  // newest posted
};

}  // namespace nibrig::rt
