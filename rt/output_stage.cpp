#include "rt/output_stage.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace nibrig::rt {
namespace {

constexpr double kPreClip = 4.0;  // × limit
// The release approaches 1 geometrically and would stop a rounding step short of it, keeping every
// later sample on the limiter's slow path; this close (1e-11 dB) it is 1.
constexpr double kGainOne = 1e-12;

bool all_finite(const float* x, std::size_t count) noexcept {
  bool finite = true;
  for (std::size_t i = 0; i < count; ++i)
    finite &= std::abs(x[i]) <= std::numeric_limits<float>::max();
  return finite;
}

}  // namespace

OutputStage::OutputStage(const OutputStageSettings& s) {
  const bool positive = s.sample_rate_hz > 0 && s.dc_corner_hz > 0 && s.limit > 0 &&
                        s.release_s > 0 && std::isfinite(s.sample_rate_hz) &&
                        std::isfinite(s.limit) && std::isfinite(s.release_s);
  if (!positive || s.dc_corner_hz >= 0.5 * s.sample_rate_hz)
    throw std::invalid_argument(
        "output stage: rate, DC corner (below Nyquist), limit and release must be positive");
  // R = e^(−2π f_c / f_s), the matched-z pole: at corners this far below the sample rate the
  // filter's −3 dB point lies at f_c to well under 1 %.
  pole_ = std::exp(-2.0 * std::numbers::pi * s.dc_corner_hz / s.sample_rate_hz);
  pole_powers_[0] = pole_;
  for (std::size_t j = 1; j < 4; ++j) pole_powers_[j] = pole_powers_[j - 1] * pole_;
  release_step_ = 1.0 - std::exp(-1.0 / (s.release_s * s.sample_rate_hz));
  limit_ = s.limit;
  // The samples are floats: the bound is the largest float not above the limit.
  limit_float_ = static_cast<float>(s.limit);
  if (static_cast<double>(limit_float_) > s.limit) limit_float_ = std::nextafter(limit_float_, 0.0f);
}

void OutputStage::process(float* samples, std::size_t count) noexcept {
  double filtered[kChunk];
  for (std::size_t at = 0; at < count; at += kChunk) {
    const std::size_t n = std::min(kChunk, count - at);
    if (all_finite(samples + at, n))
      high_pass_grouped(samples + at, filtered, n);
    else
      high_pass_guarded(samples + at, filtered, n);
    limit(filtered, samples + at, n);
  }
}

// Inputs far beyond the limit (a runaway voice, a huge gain) are clipped before the high-pass: the
// limiter would crush them anyway, and unclipped they would leave the filter's memory so large that
// its 5 Hz decay held the output at the limit for seconds after the fault ended. Tiny outputs are
// flushed: a decaying filter state far below audibility would otherwise slow every later sample.
//
// Four samples a step: y[g+j] = e[j] + R^(j+1)·y[g−1], where e is the group's own inputs filtered
// from rest. Only the last line waits for the step before, so the serial chain is a quarter as
// long.
void OutputStage::high_pass_grouped(const float* in, double* out, std::size_t count) noexcept {
  const double clip = kPreClip * limit_, pole = pole_;  // locals: `out` could alias a member
  const double powers[4] = {pole_powers_[0], pole_powers_[1], pole_powers_[2], pole_powers_[3]};
  double state = previous_output_, previous = previous_input_;
  std::size_t i = 0;
  for (; i + 4 <= count; i += 4) {
    double e[4];
    for (std::size_t j = 0; j < 4; ++j) {
      const double x = std::clamp(static_cast<double>(in[i + j]), -clip, clip);
      e[j] = x - previous + (j ? pole * e[j - 1] : 0.0);
      previous = x;
    }
    for (std::size_t j = 0; j < 4; ++j) {
      const double y = e[j] + powers[j] * state;
      out[i + j] = std::abs(y) < 1e-30 ? 0.0 : y;
    }
    state = out[i + 3];
  }
  for (; i < count; ++i) {
    const double x = std::clamp(static_cast<double>(in[i]), -clip, clip);
    const double y = x - previous + pole * state;
    previous = x;
    state = out[i] = std::abs(y) < 1e-30 ? 0.0 : y;
  }
  previous_input_ = previous;
  previous_output_ = state;
}

// A chunk with NaN or infinity: those samples become silence, and the filter's memory is cleared so
// that one bad sample cannot ring on as a step.
void OutputStage::high_pass_guarded(const float* in, double* out, std::size_t count) noexcept {
  const double clip = kPreClip * limit_;
  for (std::size_t i = 0; i < count; ++i) {
    double x = in[i];
    if (!std::isfinite(x)) {
      ++counts_.non_finite_samples;
      x = 0.0;
      previous_input_ = previous_output_ = 0.0;
    }
    x = std::clamp(x, -clip, clip);
    const double y = x - previous_input_ + pole_ * previous_output_;
    previous_input_ = x;
    previous_output_ = out[i] = std::abs(y) < 1e-30 ? 0.0 : y;
  }
}

// Peak limiter: instant attack (the gain drops at once to what keeps this sample at the limit),
// exponential release back towards 1. The round-off guard keeps |out| ≤ limit exactly in the floats
// handed on. At a gain of 1 and no sample above the limit, every step would leave the gain at 1, so
// the chunk is converted without them.
void OutputStage::limit(const double* in, float* out, std::size_t count) noexcept {
  double largest = 0;
  for (std::size_t i = 0; i < count; ++i) largest = std::max(largest, std::abs(in[i]));
  float peak = static_cast<float>(counts_.peak);
  const float bound = limit_float_;
  if (gain_ == 1.0 && largest <= limit_) {
    constexpr std::size_t kLanes = 8;  // the peak in lanes, so the loop is not one chain of maxima
    float lanes[kLanes] = {};
    std::size_t i = 0;
    for (; i + kLanes <= count; i += kLanes)
      for (std::size_t q = 0; q < kLanes; ++q) {
        const float y = std::clamp(static_cast<float>(in[i + q]), -bound, bound);
        out[i + q] = y;
        lanes[q] = std::max(lanes[q], std::abs(y));
      }
    for (; i < count; ++i) {
      out[i] = std::clamp(static_cast<float>(in[i]), -bound, bound);
      peak = std::max(peak, std::abs(out[i]));
    }
    for (float lane : lanes) peak = std::max(peak, lane);
  } else {
    for (std::size_t i = 0; i < count; ++i) {
      gain_ += (1.0 - gain_) * release_step_;
      if (1.0 - gain_ < kGainOne) gain_ = 1.0;
      const double magnitude = std::abs(in[i]) * gain_;
      if (magnitude > limit_) {
        gain_ = limit_ / std::abs(in[i]);
        ++counts_.limited_samples;
      }
      const float y = std::clamp(static_cast<float>(in[i] * gain_), -bound, bound);
      out[i] = y;
      peak = std::max(peak, std::abs(y));
    }
  }
  counts_.peak = std::max(counts_.peak, static_cast<double>(peak));
}

}  // namespace nibrig::rt
