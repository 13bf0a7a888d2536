// A tool-surface forcing spectrum F(f, v) made ready for the forcing generator: for each measured
// speed, the magnitude of every frequency bin of the generator's synthesis frames. Built on a
// control thread (it allocates and may throw); read on the audio thread.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "model/io/velocity_spectrum.hpp"
#include "model/numeric/amplitude_convention.hpp"

namespace nibrig::rt {

class ForcingTable {
 public:
  // `target`: amplitude_m_s2 holds the forcing in N (the field name is the catalog's), as the
  // catalog's mean |FFT|·2/N over rectangular windows of window_seconds, at frequencies_hz for
  // each of speeds_m_s. The generator's frames are the power of two at or above one second at
  // sample_rate_hz (4096 at 4 kHz: 0.98 Hz bins, finer than the catalog's 2 Hz grid). Bins outside
  // the target's frequency range get nothing (no DC, nothing above its last frequency); inside,
  // the amplitude is interpolated linearly in frequency.
  //
  // Throws std::invalid_argument for an empty or inconsistent spectrum, negative or non-finite
  // amplitudes, speeds that are not positive and increasing, a non-positive rate or window, or a
  // last frequency at or above the Nyquist frequency.
  ForcingTable(const model::io::VelocitySpectrum& target, double sample_rate_hz,
               double window_seconds = model::numeric::kCatalogWindowSeconds);

  double sample_rate() const noexcept { return sample_rate_; }
  std::size_t frame_length() const noexcept { return frame_length_; }
  std::size_t bins() const noexcept { return frame_length_ / 2 + 1; }
  const std::vector<double>& speeds() const noexcept { return speeds_; }
  // The FFT-bin magnitudes for speeds()[s], scaled so that a frame made from them and unit complex
  // Gaussian noise, windowed and overlap-added as the generator does, has the target PSD.
  std::span<const double> magnitudes(std::size_t s) const noexcept {
    return {magnitudes_.data() + s * bins(), bins()};
  }
  // One past the last bin that any speed's magnitudes reach: the bins above are zero for every
  // speed (the target ends far below the Nyquist frequency), so a frame's spectrum is made up to
  // it.
  std::size_t active_bins() const noexcept { return active_bins_; }

 private:
  double sample_rate_;
  std::size_t frame_length_;
  std::size_t active_bins_ = 0;
  std::vector<double> speeds_;
  std::vector<double> magnitudes_;  // speeds × bins, row-major
};

}  // namespace nibrig::rt
