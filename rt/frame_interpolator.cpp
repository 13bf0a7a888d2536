#include "rt/frame_interpolator.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "model/numeric/cpu_features.hpp"
#include "rt/kaiser_window.hpp"

namespace nibrig::rt {
namespace {

constexpr std::size_t kPhasesPerVector = 4;  // AVX2's doubles
// The design's stop band. Kaiser's formulas are estimates, and a generator's error came out at
// -79 dB with a design for 80; 90 keeps its frames within 80 dB of the full-rate ones.
constexpr double kStopBandDb = 90.0;

std::size_t choose_factor(std::size_t frame_length, std::size_t active_bins) {
  for (std::size_t factor : {8u, 4u, 2u})
    if (frame_length % factor == 0 && 3 * active_bins <= frame_length / factor) return factor;
  return 1;
}

// Four doubles: a register of AVX2, two of SSE2 in the portable build.
using Vector = double __attribute__((vector_size(kPhasesPerVector * sizeof(double))));

// out[(m + b)·F + r] = Σ_j by_tap[j·stride + r]·x[m + b + j] for b < B: B outputs summed together,
// since each one's sum is a chain of dependent multiply-adds. An output's phases are side by side
// in vectors, for a factor F of 2, 4 or 8 known when compiled (a run-time count made the phases'
// stores a call to memmove).
template <std::size_t F, std::size_t B>
[[gnu::always_inline]] inline void run_outputs(const double* __restrict by_tap, std::size_t taps,
                                               const double* __restrict x, std::size_t m,
                                               double* __restrict out) noexcept {
  constexpr std::size_t kVectors = F <= kPhasesPerVector ? 1 : F / kPhasesPerVector;
  constexpr std::size_t kStride = kVectors * kPhasesPerVector;
  Vector sum[B][kVectors] = {};
  for (std::size_t j = 0; j < taps; ++j)
    for (std::size_t v = 0; v < kVectors; ++v) {
      Vector t;  // by_tap is a std::vector's, aligned for a double only
      __builtin_memcpy(&t, by_tap + (j * kVectors + v) * kPhasesPerVector, sizeof t);
      for (std::size_t b = 0; b < B; ++b) sum[b][v] += t * x[m + b + j];
    }
  for (std::size_t b = 0; b < B; ++b) {
    double lanes[kStride];
    __builtin_memcpy(lanes, sum[b], sizeof lanes);
    for (std::size_t r = 0; r < F; ++r) out[(m + b) * F + r] = lanes[r];
  }
}

// Outputs [0, count): four at a time, then one at a time.
template <std::size_t F>
[[gnu::always_inline]] inline void run(const double* __restrict by_tap, std::size_t taps,
                                       const double* __restrict x, std::size_t count,
                                       double* __restrict out) noexcept {
  constexpr std::size_t kBlock = 4;
  std::size_t m = 0;
  for (; m + kBlock <= count; m += kBlock) run_outputs<F, kBlock>(by_tap, taps, x, m, out);
  for (; m < count; ++m) run_outputs<F, 1>(by_tap, taps, x, m, out);
}

[[gnu::always_inline]] inline void run_factor(const double* by_tap, std::size_t taps,
                                              std::size_t factor, const double* x,
                                              std::size_t count, double* out) noexcept {
  switch (factor) {
    case 2:
      return run<2>(by_tap, taps, x, count, out);
    case 4:
      return run<4>(by_tap, taps, x, count, out);
    default:
      return run<8>(by_tap, taps, x, count, out);
  }
}

void run_portable(const double* by_tap, std::size_t taps, std::size_t factor, const double* x,
                  std::size_t count, double* out) noexcept {
  run_factor(by_tap, taps, factor, x, count, out);
}

// With FMA: the frames come from FFTW, whose rounding already depends on the CPU's vector units.
[[gnu::target("avx2,fma")]] void run_avx2_fma(const double* by_tap, std::size_t taps,
                                              std::size_t factor, const double* x,
                                              std::size_t count, double* out) noexcept {
  run_factor(by_tap, taps, factor, x, count, out);
}

}  // namespace

FrameInterpolator::FrameInterpolator(std::size_t frame_length, std::size_t active_bins,
                                     FrameRate rate)
    : frame_length_(frame_length),
      factor_(rate == FrameRate::full ? 1 : choose_factor(frame_length, active_bins)),
      avx2_fma_(model::numeric::cpu_has_avx2_fma()) {
  if (factor_ == 1) return;
  const std::size_t reduced = frame_length / factor_;
  // The transition runs from the band's top to its first image (the reduced rate less the top),
  // as a fraction of the full rate; Kaiser's length for the stop band over it, in full-rate
  // samples, gives the taps: an even number of reduced-rate samples.
  const double transition =
      (static_cast<double>(reduced) - 2.0 * static_cast<double>(active_bins)) /
      static_cast<double>(frame_length);
  const double length = kaiser_length(kStopBandDb, transition);
  taps_ = 2 * static_cast<std::size_t>(std::ceil(length / static_cast<double>(2 * factor_)));
  if (taps_ >= reduced) {  // a frame too short to be worth it
    factor_ = 1;
    taps_ = 0;
    return;
  }
  const std::size_t stride = factor_ <= kPhasesPerVector ? kPhasesPerVector : 2 * kPhasesPerVector;
  by_tap_.assign(taps_ * stride, 0.0);
  // Output phase r of reduced sample m lies r/factor after it; tap j reads reduced sample
  // m + j − (taps/2 − 1), at x = r/factor + taps/2 − 1 − j reduced samples from the output. The
  // sinc is cut off at half the reduced rate, halfway between the band's top and its image; each
  // phase is normalised to sum 1, and phase 0 is exactly the reduced sample.
  const double half = static_cast<double>(taps_) / 2.0;
  for (std::size_t r = 0; r < factor_; ++r) {
    double sum = 0;
    for (std::size_t j = 0; j < taps_; ++j) {
      const double x = static_cast<double>(r) / static_cast<double>(factor_) + half - 1.0 -
                       static_cast<double>(j);
      const double kaiser = kaiser_window(x / half, kaiser_beta(kStopBandDb));
      // At whole x (phase 0) the sinc is exactly 0 or 1, not sin(πx)'s rounding.
      const double sinc = x == 0   ? 1.0
                          : r == 0 ? 0.0
                                   : std::sin(std::numbers::pi * x) / (std::numbers::pi * x);
      by_tap_[j * stride + r] = sinc * kaiser;
      sum += sinc * kaiser;
    }
    for (std::size_t j = 0; j < taps_; ++j) by_tap_[j * stride + r] /= sum;
  }
  ends_.assign(3 * (taps_ - 1), 0.0);
}

void FrameInterpolator::interpolate(const double* reduced, double* out) noexcept {
  if (factor_ == 1) {
    std::copy_n(reduced, frame_length_, out);
    return;
  }
  // Output m reads reduced samples m − before to m + after, wrapped around the frame's ends: the
  // middle reads the frame in place, the first `before` and last `after` outputs read short copies
  // of the ends (copying the whole frame cost as much as the interpolation).
  const std::size_t n = reduced_length(), before = taps_ / 2 - 1, after = taps_ - 1 - before;
  double* head = ends_.data();  // reduced[n − before, n), then reduced[0, taps − 1)
  double* tail =
      ends_.data() + before + taps_ - 1;  // reduced[n − after − before, n), then [0, after)
  std::copy_n(reduced + n - before, before, head);
  std::copy_n(reduced, taps_ - 1, head + before);
  std::copy_n(reduced + n - after - before, after + before, tail);
  std::copy_n(reduced, after, tail + after + before);
  auto run = avx2_fma_ ? run_avx2_fma : run_portable;
  const double* by_tap = by_tap_.data();
  run(by_tap, taps_, factor_, head, before, out);
  run(by_tap, taps_, factor_, reduced, n - before - after, out + before * factor_);
  run(by_tap, taps_, factor_, tail, after, out + (n - after) * factor_);
}

}  // namespace nibrig::rt
