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

  // Phase p's tap on the input `lag` steps back (for a test of the sums' order).
  double tap(std::size_t phase, std::size_t lag) const noexcept {
    return by_lag_[lag * stride_ + phase];
  }

 private:
  static constexpr std::size_t kChunk = 64;  // inputs whose outputs are made together

  void compute_rows(const double* in, std::size_t inputs) noexcept;

  std::size_t factor_, taps_;
  std::size_t stride_;  // factor rounded up to a whole vector of phases
  // The taps by lag: lag l's taps for every phase at [l·stride, l·stride + factor), so that an
  // input's `factor` outputs are made together, a vector of phases at a time.
  std::vector<double> by_lag_;
  std::vector<double> line_;  // the last taps − 1 inputs, then the chunk being computed
  std::vector<double>
      rows_;             // the chunk's outputs: input i's phases at [i·stride, i·stride + factor)
  std::size_t row_ = 0;  // rows_'s row of the newest input
  std::size_t phase_ = 0;  // phase of the next output
  bool avx2_;              // the AVX2 loop: asked here, not on the audio thread
};

}  // namespace nibrig::rt
