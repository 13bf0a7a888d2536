// The forcing generator's frames are band-limited far below their rate (the catalog ends at 500 Hz,
// the voices run at 8 kHz), so each is made at a fraction of the rate, by an inverse FFT that many
// times shorter, and brought back to the full rate here. A frame is one period of a periodic signal
// (an inverse FFT's output), so the interpolation wraps around its ends: a polyphase
// Kaiser-windowed sinc, cut off halfway between the band's top and its first image, designed for 90
// dB.
#pragma once

#include <cstddef>
#include <vector>

namespace nibrig::rt {

// How a frame's inverse FFT is made: at a fraction of its rate and interpolated back (within 80 dB
// of the full-rate frame, several times faster), or at the full rate (the reference the reduced
// one is tested against; interpolate() is then a copy).
enum class FrameRate { reduced, full };

class FrameInterpolator {
 public:
  // The largest factor (1, 2, 4 or 8, dividing frame_length) whose reduced rate keeps the first
  // image at least one band above the band (the band's top at most a third of the reduced rate),
  // for a band of `active_bins` bins of a frame_length-point frame; 1 at FrameRate::full.
  // Allocates (control thread).
  FrameInterpolator(std::size_t frame_length, std::size_t active_bins,
                    FrameRate rate = FrameRate::reduced);

  std::size_t factor() const noexcept { return factor_; }
  std::size_t reduced_length() const noexcept { return frame_length_ / factor_; }

  // out[0, frame_length) from reduced[0, reduced_length()), reduced[m] being out[m·factor]
  // (which comes back exactly). With a factor of 1, a copy. No allocation, lock or exception.
  void interpolate(const double* reduced, double* out) noexcept;

 private:
  std::size_t frame_length_, factor_, taps_ = 0;
  bool avx2_fma_;               // the AVX2 loop: asked here, not on the audio thread
  std::vector<double> by_tap_;  // tap j's coefficient for phase r at [j·stride + r], stride 4 or 8
  std::vector<double> ends_;    // copies of the reduced frame's ends, wrapped (see interpolate)
};

}  // namespace nibrig::rt
