#include "playback/inverse_filter.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "model/numeric/real_fft.hpp"

namespace nibrig::playback {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

void require(bool condition, const std::string& message) {
  if (!condition) throw std::invalid_argument("inverse filter: " + message);
}

double median(std::vector<double> v) {
  const auto middle = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), middle, v.end());
  return *middle;
}

void check_response(const FrequencyResponse& c, const InverseFilterSettings& s) {
  require(c.frequencies_hz.size() == c.values.size(), "frequencies and values differ in count");
  require(c.frequencies_hz.size() >= 2, "the response needs at least two frequencies");
  for (std::size_t i = 0; i < c.values.size(); ++i) {
    require(std::isfinite(c.frequencies_hz[i]) && c.frequencies_hz[i] > 0 &&
                (i == 0 || c.frequencies_hz[i] > c.frequencies_hz[i - 1]),
            "frequencies must be positive and strictly increasing");
    require(std::isfinite(std::abs(c.values[i])) && std::abs(c.values[i]) > 0,
            "response values must be finite and non-zero");
  }
  require(c.frequencies_hz.front() <= s.band_low_hz && c.frequencies_hz.back() >= s.band_high_hz,
          "the response must cover the band " + std::to_string(s.band_low_hz) + "-" +
              std::to_string(s.band_high_hz) + " Hz");
}

// |C| at f: linear in log-magnitude against log-frequency between measured points (a resonance's
// skirts and a roll-off are straight lines there), held at the end values beyond them.
class MagnitudeInterpolator {
 public:
  explicit MagnitudeInterpolator(const FrequencyResponse& c) {
    for (std::size_t i = 0; i < c.values.size(); ++i) {
      log_f_.push_back(std::log(c.frequencies_hz[i]));
      log_m_.push_back(std::log(std::abs(c.values[i])));
    }
  }
  double operator()(double f) const {
    if (f <= 0 || std::log(f) <= log_f_.front()) return std::exp(log_m_.front());
    const double x = std::log(f);
    if (x >= log_f_.back()) return std::exp(log_m_.back());
    const std::size_t i = static_cast<std::size_t>(
        std::upper_bound(log_f_.begin(), log_f_.end(), x) - log_f_.begin());
    const double t = (x - log_f_[i - 1]) / (log_f_[i] - log_f_[i - 1]);
    return std::exp(log_m_[i - 1] + t * (log_m_[i] - log_m_[i - 1]));
  }

 private:
  std::vector<double> log_f_, log_m_;
};

std::size_t design_size(std::size_t taps) {
  // The real cepstrum of a sampled log-magnitude aliases in time; 32 × the taps (and at least
  // 8192 points) keeps the aliased part of a response as sharp as a Q = 3 resonance negligible.
  std::size_t m = 8192;
  while (m < 32 * taps) m *= 2;
  return m;
}

// The minimum-phase sequence with magnitude `magnitude` (M/2 + 1 bins of an M-point grid), by the
// real cepstrum: fold the cepstrum onto positive quefrencies, exponentiate, transform back.
std::vector<double> minimum_phase(const std::vector<double>& magnitude, std::size_t m) {
  model::numeric::RealFft fft(m, model::numeric::RealFft::Plans::forward_and_backward);
  auto spectrum = fft.spectrum();
  for (std::size_t k = 0; k < spectrum.size(); ++k) spectrum[k] = std::log(magnitude[k]);
  fft.backward();
  auto cepstrum = fft.real();
  const double scale = 1.0 / static_cast<double>(m);
  cepstrum[0] *= scale;
  for (std::size_t n = 1; n < m / 2; ++n) cepstrum[n] *= 2.0 * scale;
  cepstrum[m / 2] *= scale;
  for (std::size_t n = m / 2 + 1; n < m; ++n) cepstrum[n] = 0.0;
  fft.forward();
  for (auto& v : spectrum) v = std::exp(v);
  fft.backward();
  std::vector<double> h(fft.real().begin(), fft.real().end());
  for (double& v : h) v *= scale;
  return h;
}

// |H| of the taps on the M-point grid, by one zero-padded FFT.
std::vector<double> fir_magnitude(const std::vector<double>& taps, std::size_t m) {
  model::numeric::RealFft fft(m, model::numeric::RealFft::Plans::forward);
  std::fill(fft.real().begin(), fft.real().end(), 0.0);
  std::copy(taps.begin(), taps.end(), fft.real().begin());
  fft.forward();
  std::vector<double> magnitude;
  for (const auto& v : fft.spectrum()) magnitude.push_back(std::abs(v));
  return magnitude;
}

}  // namespace

std::complex<double> fir_response(std::span<const double> taps, double frequency_hz,
                                  double sample_rate_hz) {
  const std::complex<double> step = std::polar(1.0, -kTwoPi * frequency_hz / sample_rate_hz);
  std::complex<double> sum = 0.0, phasor = 1.0;
  for (double t : taps) {
    sum += t * phasor;
    phasor *= step;
  }
  return sum;
}

double fir_group_delay_s(std::span<const double> taps, double frequency_hz, double sample_rate_hz) {
  const std::complex<double> step = std::polar(1.0, -kTwoPi * frequency_hz / sample_rate_hz);
  std::complex<double> sum = 0.0, weighted = 0.0, phasor = 1.0;
  for (std::size_t n = 0; n < taps.size(); ++n) {
    sum += taps[n] * phasor;
    weighted += static_cast<double>(n) * taps[n] * phasor;
    phasor *= step;
  }
  return (weighted / sum).real() / sample_rate_hz;
}

InverseFilter design_inverse_filter(const FrequencyResponse& chain,
                                    const InverseFilterSettings& s) {
  require(
      std::isfinite(s.sample_rate_hz) && s.sample_rate_hz >= 2000.0 && s.sample_rate_hz <= 8000.0,
      "sample rate must be 2 to 8 kHz, got " + std::to_string(s.sample_rate_hz));
  require(s.taps >= 16 && s.taps <= 65536, "taps must be 16 to 65536");
  require(s.band_low_hz > 0 && s.band_high_hz > s.band_low_hz &&
              s.band_high_hz < 0.5 * s.sample_rate_hz,
          "band must be positive, ordered and below Nyquist");
  require(s.in_band_regularisation > 0 && s.low_corner_hz > 0 && s.high_corner_hz > 0 &&
              s.max_boost_db > 0,
          "regularisation and maximum boost must be positive");
  check_response(chain, s);

  const std::size_t m = design_size(s.taps);
  const std::size_t bins = m / 2 + 1;
  const double df = s.sample_rate_hz / static_cast<double>(m);
  const MagnitudeInterpolator interpolate(chain);
  std::vector<double> c(bins);
  std::vector<std::size_t> band;
  for (std::size_t k = 0; k < bins; ++k) {
    const double f = static_cast<double>(k) * df;
    c[k] = interpolate(f);
    if (f >= s.band_low_hz && f <= s.band_high_hz) band.push_back(k);
  }
  std::vector<double> band_power;
  for (std::size_t k : band) band_power.push_back(c[k] * c[k]);
  const double beta0 = s.in_band_regularisation * median(band_power);

  InverseFilter out;
  out.sample_rate_hz = s.sample_rate_hz;
  auto regularised = [&](double magnitude) { return magnitude / (magnitude * magnitude + beta0); };
  const double g_low = regularised(interpolate(s.band_low_hz));
  const double g_high = regularised(interpolate(s.band_high_hz));
  std::vector<double> g(bins);
  for (std::size_t k = 0; k < bins; ++k) {
    const double f = static_cast<double>(k) * df;
    if (f < s.band_low_hz) {
      // |first-order high-pass at the corner| relative to its value at the band edge.
      const double r = s.low_corner_hz;
      g[k] = g_low * (f / std::hypot(f, r)) / (s.band_low_hz / std::hypot(s.band_low_hz, r));
    } else if (f > s.band_high_hz) {
      const double r = s.high_corner_hz;
      g[k] = g_high * (r / std::hypot(f, r)) / (r / std::hypot(s.band_high_hz, r));
    } else {
      g[k] = regularised(c[k]);
    }
  }
  std::vector<double> band_gain;
  for (std::size_t k : band) band_gain.push_back(g[k]);
  const double cap = median(band_gain) * std::pow(10.0, s.max_boost_db / 20.0);
  for (std::size_t k = 0; k < bins; ++k) {
    if (g[k] <= cap) continue;
    g[k] = cap;
    const double f = static_cast<double>(k) * df;
    if (!out.boost_limited.empty() && out.boost_limited.back().high_hz + 1.5 * df >= f) {
      out.boost_limited.back().high_hz = f;
    } else {
      out.boost_limited.push_back({f, f});
    }
  }
  // A floor far below anything audible keeps the log finite where β has driven the gain to 0.
  const double floor = cap * 1e-8;
  for (double& v : g) v = std::max(v, floor);

  std::vector<double> h = minimum_phase(g, m);
  h.resize(s.taps);
  // A raised-cosine fall over the last fifth: the minimum-phase response has not quite decayed by
  // the last tap, and cutting it abruptly leaves a ripple of period fs/taps (16 Hz at 4 kHz and 256
  // taps) over the band; the taper trades it for a slight smoothing.
  const std::size_t fall = s.taps / 5;
  for (std::size_t i = 0; i < fall; ++i) {
    h[s.taps - fall + i] *= 0.5 + 0.5 * std::cos(std::numbers::pi * (static_cast<double>(i) + 0.5) /
                                                 static_cast<double>(fall));
  }

  // Unit gain: the median of |C·G| over the band is 1 (the regularisation and the truncation both
  // leave it slightly off); then 1 m/s² requested gives 1 m/s² at the accelerometer.
  std::vector<double> gains = fir_magnitude(h, m);
  std::vector<double> flat;
  for (std::size_t k : band) flat.push_back(c[k] * gains[k]);
  const double scale = 1.0 / median(flat);
  for (double& v : h) v *= scale;
  for (double& v : gains) v *= scale;

  double sum_square = 0.0;
  for (std::size_t k : band) {
    const double deviation = 20.0 * std::log10(c[k] * gains[k]);
    out.max_deviation_db = std::max(out.max_deviation_db, std::abs(deviation));
    sum_square += deviation * deviation;
  }
  out.rms_deviation_db = std::sqrt(sum_square / static_cast<double>(band.size()));
  std::vector<double> band_taps_gain;
  for (std::size_t k : band) band_taps_gain.push_back(gains[k]);
  const double median_gain = median(band_taps_gain);
  out.max_boost_db = 20.0 * std::log10(*std::max_element(gains.begin(), gains.end()) / median_gain);
  out.group_delay_100hz_s = fir_group_delay_s(h, 100.0, s.sample_rate_hz);
  out.taps = std::move(h);
  return out;
}

}  // namespace nibrig::playback
