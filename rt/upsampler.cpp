#include "rt/upsampler.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace nibrig::rt {
namespace {

// Kaiser's β for about 80 dB of stop-band attenuation (Kaiser's formula 0.1102·(A − 8.7)).
constexpr double kKaiserBeta = 0.1102 * (80.0 - 8.7);

}  // namespace

Upsampler::Upsampler(std::size_t factor, std::size_t taps_per_phase)
    : factor_(factor), taps_(taps_per_phase) {
  if (factor == 0 || taps_per_phase == 0)
    throw std::invalid_argument("an upsampler needs a factor and taps per phase of at least 1");
  const std::size_t length = factor * taps_per_phase;
  const double centre = (static_cast<double>(length) - 1.0) / 2.0;
  std::vector<double> prototype(length);
  for (std::size_t i = 0; i < length; ++i) {
    const double t = (static_cast<double>(i) - centre) / static_cast<double>(factor);  // inputs
    const double sinc = t == 0 ? 1.0 : std::sin(std::numbers::pi * t) / (std::numbers::pi * t);
    const double r = (static_cast<double>(i) - centre) / (centre + 0.5);
    const double kaiser = std::cyl_bessel_i(0.0, kKaiserBeta * std::sqrt(std::max(0.0, 1 - r * r))) /
                          std::cyl_bessel_i(0.0, kKaiserBeta);
    prototype[i] = sinc * kaiser;
  }
  // Output phase p (p outputs after an input arrived) uses prototype[p + l·factor] on the input
  // l steps back; each phase normalised to sum 1.
  phases_.resize(length);
  for (std::size_t p = 0; p < factor; ++p) {
    double sum = 0;
    for (std::size_t l = 0; l < taps_; ++l) sum += prototype[p + l * factor];
    for (std::size_t l = 0; l < taps_; ++l) phases_[p * taps_ + l] = prototype[p + l * factor] / sum;
  }
  history_.assign(2 * taps_, 0.0);
}

std::size_t Upsampler::inputs_needed(std::size_t frames) const noexcept {
  const std::size_t first = (factor_ - phase_) % factor_;  // first output that takes an input
  return first < frames ? (frames - 1 - first) / factor_ + 1 : 0;
}

void Upsampler::process(const double* in, float* out, std::size_t frames) noexcept {
  for (std::size_t j = 0; j < frames; ++j) {
    if (phase_ == 0) {
      newest_ = newest_ == 0 ? taps_ - 1 : newest_ - 1;
      history_[newest_] = history_[newest_ + taps_] = *in++;
    }
    const double* taps = phases_.data() + phase_ * taps_;
    const double* x = history_.data() + newest_;  // x[l] = the input l steps back
    double y = 0;
    for (std::size_t l = 0; l < taps_; ++l) y += taps[l] * x[l];
    out[j] = static_cast<float>(y);
    phase_ = phase_ + 1 == factor_ ? 0 : phase_ + 1;
  }
}

void Upsampler::reset() noexcept {
  std::fill(history_.begin(), history_.end(), 0.0);
  newest_ = 0;
  phase_ = 0;
}

}  // namespace nibrig::rt
