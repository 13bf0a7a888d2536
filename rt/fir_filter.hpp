// A streaming FIR filter for the audio thread: how the actuator's inverse filter (playback/
// inverse_filter.hpp) is applied to the engine's output at its internal rate. The taps are fixed at
// construction; process() never allocates, locks or throws.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace nibrig::rt {

class FirFilter {
 public:
  // y[n] = Σ_k taps[k]·x[n−k]. Throws std::invalid_argument for no taps or a non-finite tap (on a
  // control thread, at construction).
  explicit FirFilter(std::span<const double> taps);

  // In place, continuing from the history of earlier calls. A non-finite input makes the next
  // size() outputs non-finite and is then forgotten (an FIR has no feedback to keep it); the output
  // stage after it turns such samples into silence.
  void process(float* samples, std::size_t count) noexcept;
  // The same on the engine's double-precision mix.
  void process(double* samples, std::size_t count) noexcept;
  // Forgets the history, as if only zeros had been processed.
  void reset() noexcept;

  std::size_t size() const noexcept { return taps_.size(); }
  std::span<const double> taps() const noexcept { return taps_; }

 private:
  template <class Sample>
  void run(Sample* samples, std::size_t count) noexcept;

  std::vector<double> taps_;
  // The last size() inputs, stored twice (at i and i + size()), newest first from position_: the
  // window x[n], x[n−1], ... is then always contiguous and the inner loop is a plain dot product.
  std::vector<double> history_;
  std::size_t position_ = 0;
};

}  // namespace nibrig::rt
