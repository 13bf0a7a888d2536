// The forcing a tool feels as it slides over a surface, made up sample by sample on the audio
// thread from a ForcingTable: stationary Gaussian noise whose spectrum is the table's at the
// current speed, scaled by normal force. Never periodic (see forcing_generator.cpp for how), and a
// change of speed takes effect at the very next sample.
#pragma once

#include <complex>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "model/numeric/real_fft.hpp"
#include "rt/forcing_table.hpp"
#include "rt/frame_interpolator.hpp"
#include "rt/gaussian_noise.hpp"
#include "rt/reference_load.hpp"

namespace nibrig::rt {

class ForcingGenerator {
 public:
  // Keeps `table` (shared: voices of the same tool and surface can share one). Allocates frames
  // and the FFT plan here, on the control thread; the first frames are made here too, so output
  // is stationary from the first sample. Equal seeds give equal output.
  ForcingGenerator(std::shared_ptr<const ForcingTable> table, std::uint64_t seed,
                   FrameRate frame_rate = FrameRate::reduced);

  // out[i] = forcing (N) at speed[i] (m/s) and normal force[i] (N), one sample each at the
  // table's rate. Speed dependence: the amplitude spectrum is interpolated linearly between the
  // table's speeds; below the lowest it fades linearly to silence at rest (no sliding, no
  // vibration); above the highest it stays at the highest (clamped, and counted). Normal-force
  // dependence — an assumption, since the paper measured at one load only: amplitude ∝ force /
  // 2.2 N, as a Coulomb friction force and so the stick-slip excitation it drives would scale;
  // capped at kMaxNormalForceRatio; 0 N (lifted) is silence. NaN speed or force counts as 0.
  // Real-time safe: no allocation, lock or exception.
  void generate(const double* speed_m_s, const double* normal_force_n, double* out,
                std::size_t count) noexcept;

  const ForcingTable& table() const noexcept { return *table_; }
  // Samples generated above the table's highest speed (the clamp of ARCHITECTURE.md, "Science notes").
  std::uint64_t samples_above_speed_range() const noexcept { return above_range_; }

  // The work of one frame, in steps: kNoiseChunks draws of a part of Z, then one windowed inverse
  // FFT per table speed, overlap-added; and how many of the next frame's are done (for a test of
  // when they are).
  std::size_t frame_steps() const noexcept;
  std::size_t frame_steps_done() const noexcept { return steps_done_; }
  // The factor the frames' inverse FFTs are shortened by (1 at the full rate).
  std::size_t frame_rate_factor() const noexcept { return interpolator_.factor(); }

 private:
  void prepare_next_frame_step() noexcept;
  void finish_next_frame() noexcept;
  void start_next_hop() noexcept;
  double* frame_slot(std::size_t slot, std::size_t speed) noexcept {
    return frames_.data() + (slot * table_->speeds().size() + speed) * frame_;
  }

  std::shared_ptr<const ForcingTable> table_;
  GaussianNoise noise_;
  FrameInterpolator interpolator_;
  model::numeric::RealFft fft_;  // of the interpolator's reduced length
  std::size_t frame_, hop_;
  double step_phase_;  // in [0, 1): where in its share of the hop each frame step is done
  std::vector<double> window_;
  std::vector<std::complex<double>> z_;  // this frame's complex Gaussian bins
  std::vector<double> draw_re_, draw_im_, draw_scratch_;  // a chunk's Gaussian pairs
  // Two slots of speeds × frame windowed frames: the current one, whose first half already holds
  // the overlap-add of the frame before (its first half is being handed out), and the next (being
  // made, the current one's second half added to it as it is). A hop only swaps them, so no call
  // pays for moving a whole frame.
  std::vector<double> frames_;
  std::size_t current_ = 0, next_ = 1;
  std::size_t steps_done_ = 0;   // of the next frame (see frame_steps)
  std::size_t position_;         // next sample of the current hop to hand out
  std::uint64_t above_range_ = 0;
};

}  // namespace nibrig::rt
