// Raises the voices' internal rate (about 8 kHz: the rendered band ends at 500 Hz) to the device
// rate by an integer factor: a polyphase interpolator with a Kaiser-windowed sinc, flat to 500 Hz
// and removing the images around multiples of the internal rate. Audio-thread safe.
#pragma once

#include <cstddef>
#include <vector>

namespace nibrig::rt {

class Upsampler {
 public:
  // factor ≥ 1, taps_per_phase ≥ 1 (else std::invalid_argument). The prototype low-pass has
  // factor·taps_per_phase taps, cut off at half the input rate; with the default 8 taps per phase
  // it passes 0-500 Hz within 0.01 dB and attenuates images by more than 70 dB for input rates
  // of 4 kHz and up (tested). Each phase sums to exactly 1, so a constant input gives a constant output.
  explicit Upsampler(std::size_t factor, std::size_t taps_per_phase = 8);

  std::size_t factor() const noexcept { return factor_; }
  // The linear-phase delay, in output samples.
  double delay() const noexcept {
    return (static_cast<double>(factor_ * taps_) - 1.0) / 2.0;
  }
  // How many input samples the next `frames` outputs take (one at every output whose phase is 0).
  std::size_t inputs_needed(std::size_t frames) const noexcept;
  // Writes `frames` outputs, taking exactly inputs_needed(frames) samples from `in`. No
  // allocation, lock or exception.
  void process(const double* in, float* out, std::size_t frames) noexcept;
  void reset() noexcept;

 private:
  std::size_t factor_, taps_;
  std::vector<double> phases_;   // phase p's taps at [p·taps, (p+1)·taps), newest input first
  std::vector<double> history_;  // last `taps` inputs, doubled so a window is contiguous
  std::size_t newest_ = 0;       // history_ index of the newest input (and newest + taps)
  std::size_t phase_ = 0;        // phase of the next output
};

}  // namespace nibrig::rt
