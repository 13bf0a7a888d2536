#include "tests/playback/calibration_chain.hpp"

#include <array>
#include <numbers>
#include <random>

namespace nibrig::playback::testing {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// (b2 s² + b1 s + b0) / (a2 s² + a1 s + a0)
struct Analogue {
  std::array<double, 3> b, a;  // index = power of s
};

std::complex<double> evaluate(const Analogue& h, std::complex<double> s) {
  return (h.b[2] * s * s + h.b[1] * s + h.b[0]) / (h.a[2] * s * s + h.a[1] * s + h.a[0]);
}

std::vector<Analogue> sections(const ChainModel& c) {
  const double w0 = kTwoPi * c.resonance_hz, wh = kTwoPi * c.high_pass_hz;
  std::vector<Analogue> out{
      {{0.0, c.gain * w0 / c.q, 0.0}, {w0 * w0, w0 / c.q, 1.0}},
      {{0.0, 0.0, 1.0}, {wh * wh, std::numbers::sqrt2 * wh, 1.0}},
  };
  if (c.notch_hz > 0) {
    const double wn = kTwoPi * c.notch_hz;
    out.push_back({{wn * wn, 0.0, 1.0}, {wn * wn, wn / c.notch_q, 1.0}});
  }
  return out;
}

// s = c(1 − z⁻¹)/(1 + z⁻¹), c = 2 fs: the bilinear transform, term by term.
void bilinear(const Analogue& h, double fs, std::array<double, 3>& b, std::array<double, 3>& a) {
  const double c = 2.0 * fs, c2 = c * c;
  auto map = [&](const std::array<double, 3>& p, std::array<double, 3>& out) {
    out = {p[2] * c2 + p[1] * c + p[0], 2.0 * (p[0] - p[2] * c2), p[2] * c2 - p[1] * c + p[0]};
  };
  map(h.b, b);
  map(h.a, a);
  const double a0 = a[0];
  for (double& v : b) v /= a0;
  for (double& v : a) v /= a0;
}

}  // namespace

std::complex<double> analogue_response(const ChainModel& chain, double frequency_hz) {
  const std::complex<double> s(0.0, kTwoPi * frequency_hz);
  std::complex<double> h = 1.0;
  for (const Analogue& section : sections(chain)) h *= evaluate(section, s);
  return h;
}

std::vector<double> simulate(const ChainModel& chain, const std::vector<double>& input,
                             double sample_rate_hz, std::size_t delay_samples, double cubic,
                             double noise_rms, unsigned seed) {
  std::vector<double> signal(input.size());
  for (std::size_t i = 0; i < input.size(); ++i)
    signal[i] = input[i] + cubic * input[i] * input[i] * input[i];
  for (const Analogue& section : sections(chain)) {
    std::array<double, 3> b, a;
    bilinear(section, sample_rate_hz, b, a);
    double x1 = 0, x2 = 0, y1 = 0, y2 = 0;
    for (double& v : signal) {
      const double y = b[0] * v + b[1] * x1 + b[2] * x2 - a[1] * y1 - a[2] * y2;
      x2 = x1;
      x1 = v;
      y2 = y1;
      y1 = y;
      v = y;
    }
  }
  std::vector<double> out(input.size(), 0.0);
  for (std::size_t i = delay_samples; i < out.size(); ++i) out[i] = signal[i - delay_samples];
  std::mt19937 generator(seed);
  std::normal_distribution<double> noise(0.0, noise_rms);
  for (double& v : out) v += noise(generator);
  return out;
}

}  // namespace nibrig::playback::testing
