#include "rt/upsampler.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "model/numeric/cpu_features.hpp"
#include "rt/kaiser_window.hpp"

namespace nibrig::rt {
namespace {

constexpr std::size_t kLanes = 4;  // phases a vector holds (AVX2's doubles)

// rows[i·stride + p] = Σ_l by_lag[l·stride + p]·line[taps − 1 + i − l], each sum over the lags in
// order: the same bits as one output at a time, with the phases side by side in lanes. G vectors of
// phases a row (stride = G·kLanes), held in registers while an input's lags are summed.
template <std::size_t G>
[[gnu::always_inline]] inline void accumulate(const double* __restrict by_lag, std::size_t taps,
                                              const double* __restrict line,
                                              double* __restrict rows,
                                              std::size_t inputs) noexcept {
  constexpr std::size_t kStride = G * kLanes;
  for (std::size_t i = 0; i < inputs; ++i) {
    double sum[kStride] = {};
    for (std::size_t l = 0; l < taps; ++l) {
      const double x = line[taps - 1 + i - l];
      for (std::size_t p = 0; p < kStride; ++p) sum[p] += by_lag[l * kStride + p] * x;
    }
    for (std::size_t p = 0; p < kStride; ++p) rows[i * kStride + p] = sum[p];
  }
}

// The factors a device and internal rate give (48 or 44.1 kHz to 8 or 7.35 kHz: 6; 96 kHz: 12)
// need at most three vectors; larger ones are made a vector of phases at a time.
[[gnu::always_inline]] inline void accumulate_any(const double* __restrict by_lag,
                                                  std::size_t stride, std::size_t taps,
                                                  const double* __restrict line,
                                                  double* __restrict rows,
                                                  std::size_t inputs) noexcept {
  switch (stride / kLanes) {
    case 1:
      return accumulate<1>(by_lag, taps, line, rows, inputs);
    case 2:
      return accumulate<2>(by_lag, taps, line, rows, inputs);
    case 3:
      return accumulate<3>(by_lag, taps, line, rows, inputs);
    default:
      for (std::size_t i = 0; i < inputs; ++i)
        for (std::size_t g = 0; g < stride; g += kLanes) {
          double sum[kLanes] = {};
          for (std::size_t l = 0; l < taps; ++l)
            for (std::size_t q = 0; q < kLanes; ++q)
              sum[q] += by_lag[l * stride + g + q] * line[taps - 1 + i - l];
          for (std::size_t q = 0; q < kLanes; ++q) rows[i * stride + g + q] = sum[q];
        }
  }
}

// Compiled again for AVX2, without FMA, whose single rounding would change the bits.
[[gnu::target("avx2")]] void accumulate_avx2(const double* __restrict by_lag, std::size_t stride,
                                             std::size_t taps, const double* __restrict line,
                                             double* __restrict rows, std::size_t inputs) noexcept {
  accumulate_any(by_lag, stride, taps, line, rows, inputs);
}

}  // namespace

Upsampler::Upsampler(std::size_t factor, std::size_t taps_per_phase)
    : factor_(factor),
      taps_(taps_per_phase),
      stride_((factor + kLanes - 1) / kLanes * kLanes),
      avx2_(model::numeric::cpu_has_avx2_fma()) {
  if (factor == 0 || taps_per_phase == 0)
    throw std::invalid_argument("an upsampler needs a factor and taps per phase of at least 1");
  const std::size_t length = factor * taps_per_phase;
  const double centre = (static_cast<double>(length) - 1.0) / 2.0;
  std::vector<double> prototype(length);
  for (std::size_t i = 0; i < length; ++i) {
    const double t = (static_cast<double>(i) - centre) / static_cast<double>(factor);  // inputs
    const double sinc = t == 0 ? 1.0 : std::sin(std::numbers::pi * t) / (std::numbers::pi * t);
    const double r = (static_cast<double>(i) - centre) / (centre + 0.5);
    prototype[i] = sinc * kaiser_window(r, kaiser_beta(80.0));
  }
  // Output phase p (p outputs after an input arrived) uses prototype[p + l·factor] on the input
  // l steps back; each phase normalised to sum 1. The padding phases stay 0.
  by_lag_.assign(taps_ * stride_, 0.0);
  for (std::size_t p = 0; p < factor; ++p) {
    double sum = 0;
    for (std::size_t l = 0; l < taps_; ++l) sum += prototype[p + l * factor];
    for (std::size_t l = 0; l < taps_; ++l)
      by_lag_[l * stride_ + p] = prototype[p + l * factor] / sum;
  }
  line_.assign(taps_ - 1 + kChunk, 0.0);
  rows_.assign(kChunk * stride_, 0.0);
}

std::size_t Upsampler::inputs_needed(std::size_t frames) const noexcept {
  const std::size_t first = (factor_ - phase_) % factor_;  // first output that takes an input
  return first < frames ? (frames - 1 - first) / factor_ + 1 : 0;
}

void Upsampler::compute_rows(const double* in, std::size_t inputs) noexcept {
  std::copy_n(in, inputs, line_.data() + taps_ - 1);
  if (avx2_)
    accumulate_avx2(by_lag_.data(), stride_, taps_, line_.data(), rows_.data(), inputs);
  else
    accumulate_any(by_lag_.data(), stride_, taps_, line_.data(), rows_.data(), inputs);
  std::copy_n(line_.data() + inputs, taps_ - 1, line_.data());
}

void Upsampler::process(const double* in, float* out, std::size_t frames) noexcept {
  std::size_t j = 0, phase = phase_;  // locals: the stores to `out` could otherwise alias them
  std::size_t row = row_, rows = row_ + 1;  // the newest input's outputs are still in rows_
  while (j < frames) {
    if (phase == 0) {
      if (++row == rows) {
        const std::size_t inputs = std::min(kChunk, (frames - j + factor_ - 1) / factor_);
        compute_rows(in, inputs);
        in += inputs;
        row = 0;
        rows = inputs;
      }
    }
    const std::size_t run = std::min(factor_ - phase, frames - j);
    const double* outputs = rows_.data() + row * stride_ + phase;
    for (std::size_t k = 0; k < run; ++k) out[j + k] = static_cast<float>(outputs[k]);
    j += run;
    phase = phase + run == factor_ ? 0 : phase + run;
  }
  // The rows after `row` were computed for this call and all used; only `row` may have phases left.
  if (row != 0 && phase != 0) std::copy_n(rows_.data() + row * stride_, stride_, rows_.data());
  row_ = phase != 0 ? 0 : row;
  phase_ = phase;
}

void Upsampler::reset() noexcept {
  std::fill(line_.begin(), line_.end(), 0.0);
  std::fill(rows_.begin(), rows_.end(), 0.0);
  row_ = 0;
  phase_ = 0;
}

}  // namespace nibrig::rt
