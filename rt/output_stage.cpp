#include "rt/output_stage.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace nibrig::rt {
namespace {
constexpr double kPreClip = 4.0;  // × limit
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
  release_step_ = 1.0 - std::exp(-1.0 / (s.release_s * s.sample_rate_hz));
  limit_ = s.limit;
  // The samples are floats: the bound is the largest float not above the limit.
  limit_float_ = static_cast<float>(s.limit);
  if (static_cast<double>(limit_float_) > s.limit) limit_float_ = std::nextafter(limit_float_, 0.0f);
}

void OutputStage::process(float* samples, std::size_t count) noexcept {
  for (std::size_t i = 0; i < count; ++i) {
    double x = samples[i];
    if (!std::isfinite(x)) {
      // Silence, and the filter's memory cleared so that one bad sample cannot ring on as a step.
      ++counts_.non_finite_samples;
      x = 0.0;
      previous_input_ = previous_output_ = 0.0;
    }
    // Inputs far beyond the limit (a runaway voice, a huge gain) are clipped before the high-pass:
    // the limiter would crush them anyway, and unclipped they would leave the filter's memory so
    // large that its 5 Hz decay held the output at the limit for seconds after the fault ended.
    x = std::clamp(x, -kPreClip * limit_, kPreClip * limit_);
    double y = x - previous_input_ + pole_ * previous_output_;
    previous_input_ = x;
    // Flush denormals: a decaying filter state far below audibility would otherwise slow every
    // following sample on x86.
    if (std::abs(y) < 1e-30) y = 0.0;
    previous_output_ = y;
    // Peak limiter: instant attack (the gain drops at once to what keeps this sample at the limit),
    // exponential release back towards 1.
    gain_ += (1.0 - gain_) * release_step_;
    const double magnitude = std::abs(y) * gain_;
    if (magnitude > limit_) {
      gain_ = limit_ / std::abs(y);
      ++counts_.limited_samples;
    }
    // Round-off guard: the contract is |out| ≤ limit exactly, in the floats handed on.
    float out = static_cast<float>(y * gain_);
    if (out > limit_float_) out = limit_float_;
    if (out < -limit_float_) out = -limit_float_;
    samples[i] = out;
    if (std::abs(out) > counts_.peak) counts_.peak = std::abs(out);
  }
}

}  // namespace nibrig::rt
