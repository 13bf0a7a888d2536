#include "rt/fir_filter.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace nibrig::rt {

FirFilter::FirFilter(std::span<const double> taps) : taps_(taps.begin(), taps.end()) {
  if (taps_.empty()) throw std::invalid_argument("FIR filter: needs at least one tap");
  if (!std::all_of(taps_.begin(), taps_.end(), [](double t) { return std::isfinite(t); }))
    throw std::invalid_argument("FIR filter: every tap must be finite");
  history_.assign(2 * taps_.size(), 0.0);
}

void FirFilter::process(float* samples, std::size_t count) noexcept { run(samples, count); }
void FirFilter::process(double* samples, std::size_t count) noexcept { run(samples, count); }

template <class Sample>
void FirFilter::run(Sample* samples, std::size_t count) noexcept {
  const std::size_t length = taps_.size();
  const double* taps = taps_.data();
  for (std::size_t i = 0; i < count; ++i) {
    // Newest sample one place earlier, wrapping once per `length` samples: the only branch.
    position_ = position_ == 0 ? length - 1 : position_ - 1;
    const double x = samples[i];
    history_[position_] = x;
    history_[position_ + length] = x;
    const double* window = history_.data() + position_;
    // Four partial sums: without -ffast-math the compiler may not reorder one long sum, and the
    // independent chains keep the FPU pipeline full. Accumulating in double keeps a few hundred
    // products of float-sized inputs far below float resolution.
    double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
    std::size_t k = 0;
    for (; k + 4 <= length; k += 4) {
      s0 += taps[k] * window[k];
      s1 += taps[k + 1] * window[k + 1];
      s2 += taps[k + 2] * window[k + 2];
      s3 += taps[k + 3] * window[k + 3];
    }
    for (; k < length; ++k) s0 += taps[k] * window[k];
    samples[i] = static_cast<Sample>((s0 + s1) + (s2 + s3));
  }
}

void FirFilter::reset() noexcept {
  std::fill(history_.begin(), history_.end(), 0.0);
  position_ = 0;
}

}  // namespace nibrig::rt
