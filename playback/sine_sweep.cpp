#include "playback/sine_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>
#include <string>

#include "model/numeric/real_fft.hpp"

namespace nibrig::playback {
namespace {

constexpr double kPi = std::numbers::pi;
// How far before the peak the onset is looked for: more than the rise time of any chain of interest
// (a resonance's first peak comes a quarter period after the onset: 2 ms at 120 Hz), far less than
// the lead of any harmonic's product.
constexpr double kOnsetSearch_s = 0.010;
// SNR reported when the repetitions agree to the last bit (a noiseless simulation).
constexpr double kSnrCeiling_db = 200.0;

void require_sweep(bool condition, const std::string& message) {
  if (!condition) throw std::invalid_argument("sweep: " + message);
}

double sweep_rate_constant(const SineSweepSettings& s) {
  return s.duration_s / std::log(s.end_hz / s.start_hz);
}

std::size_t to_samples(double seconds, double rate) {
  return static_cast<std::size_t>(std::llround(seconds * rate));
}

// The taper of the impulse-response window: a raised-cosine rise over the part kept before the
// onset (the band-limited response's leading edge, which must not be cut abruptly) and a
// raised-cosine fall over the last fifth, where the response has decayed.
std::vector<double> impulse_window(std::size_t pre, std::size_t length) {
  std::vector<double> w(pre + length, 1.0);
  for (std::size_t i = 0; i < pre; ++i)
    w[i] = 0.5 - 0.5 * std::cos(kPi * (static_cast<double>(i) + 0.5) / static_cast<double>(pre));
  const std::size_t fall = std::max<std::size_t>(1, length / 5);
  for (std::size_t i = 0; i < fall; ++i) {
    w[pre + length - fall + i] =
        0.5 + 0.5 * std::cos(kPi * (static_cast<double>(i) + 0.5) / static_cast<double>(fall));
  }
  return w;
}

// Σ g[i]·e^(−jω(i − pre)): the windowed response's spectrum with time 0 at the onset. The phasor is
// advanced by multiplication and re-anchored every 4096 steps so that its round-off cannot grow.
std::complex<double> dtft(const std::vector<double>& g, std::size_t pre, double omega) {
  const std::complex<double> step = std::polar(1.0, -omega);
  std::complex<double> sum = 0.0;
  std::complex<double> phasor;
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (i % 4096 == 0)
      phasor = std::polar(1.0, -omega * (static_cast<double>(i) - static_cast<double>(pre)));
    sum += g[i] * phasor;
    phasor *= step;
  }
  return sum;
}

}  // namespace

void validate(const SineSweepSettings& s) {
  require_sweep(std::isfinite(s.sample_rate_hz) && s.sample_rate_hz > 0,
                "sample rate must be positive");
  require_sweep(std::isfinite(s.start_hz) && s.start_hz > 0, "start frequency must be positive");
  require_sweep(
      std::isfinite(s.end_hz) && s.end_hz > s.start_hz && s.end_hz < 0.5 * s.sample_rate_hz,
      "end frequency must lie above the start and below Nyquist (" +
          std::to_string(0.5 * s.sample_rate_hz) + " Hz)");
  require_sweep(std::isfinite(s.duration_s) && s.duration_s * s.sample_rate_hz >= 16,
                "duration must be at least 16 samples");
  require_sweep(std::isfinite(s.level) && s.level > 0 && s.level <= 1, "level must lie in (0, 1]");
  require_sweep(std::isfinite(s.fade_s) && s.fade_s >= 0 && 2 * s.fade_s <= s.duration_s,
                "fades must be non-negative and together no longer than the sweep");
  require_sweep(std::isfinite(s.silence_s) && s.silence_s > 0,
                "silence after the sweep must be positive");
  require_sweep(s.repetitions >= 1 && s.repetitions <= 100, "repetitions must be 1 to 100");
}

std::size_t sine_sweep_samples(const SineSweepSettings& s) {
  return to_samples(s.duration_s, s.sample_rate_hz);
}

std::size_t period_samples(const SineSweepSettings& s) {
  return sine_sweep_samples(s) + to_samples(s.silence_s, s.sample_rate_hz);
}

std::vector<double> exponential_sine_sweep(const SineSweepSettings& s) {
  validate(s);
  const std::size_t n_sweep = sine_sweep_samples(s);
  const std::size_t n_period = period_samples(s);
  const std::size_t n_fade = to_samples(s.fade_s, s.sample_rate_hz);
  const double L = sweep_rate_constant(s);
  std::vector<double> period(n_period, 0.0);
  for (std::size_t n = 0; n < n_sweep; ++n) {
    const double t = static_cast<double>(n) / s.sample_rate_hz;
    double x = std::sin(2.0 * kPi * s.start_hz * L * std::expm1(t / L));
    const std::size_t from_end = n_sweep - 1 - n;
    const std::size_t edge = std::min(n, from_end);
    if (edge < n_fade)
      x *= 0.5 -
           0.5 * std::cos(kPi * (static_cast<double>(edge) + 0.5) / static_cast<double>(n_fade));
    period[n] = s.level * x;
  }
  std::vector<double> signal;
  signal.reserve(n_period * static_cast<std::size_t>(s.repetitions));
  for (int r = 0; r < s.repetitions; ++r) signal.insert(signal.end(), period.begin(), period.end());
  return signal;
}

ResponseEstimate estimate_response(const SineSweepSettings& s, std::span<const double> played,
                                   std::span<const double> recorded, const EstimationSettings& e) {
  validate(s);
  require_sweep(e.pre_onset_s > 0 && e.impulse_length_s > 0 && e.onset_threshold > 0 &&
                    e.onset_threshold < 1 && e.points_per_octave > 0 && e.regularisation >= 0,
                "estimation settings must be positive (onset threshold below 1)");
  const double fs = s.sample_rate_hz;
  const std::size_t period = period_samples(s);
  const std::size_t repetitions = static_cast<std::size_t>(s.repetitions);
  const std::size_t n = period * repetitions;
  require_sweep(played.size() == n, "played signal has " + std::to_string(played.size()) +
                                        " samples, the settings give " + std::to_string(n));
  require_sweep(recorded.size() >= n, "recording has " + std::to_string(recorded.size()) +
                                          " samples, fewer than the " + std::to_string(n) +
                                          " played");

  const double L = sweep_rate_constant(s);
  ResponseEstimate out;
  out.harmonic2_lead_s = L * std::log(2.0);
  out.harmonic3_lead_s = L * std::log(3.0);
  const std::size_t pre = std::max<std::size_t>(1, to_samples(e.pre_onset_s, fs));
  const std::size_t length = to_samples(e.impulse_length_s, fs);
  const std::size_t silence = period - sine_sweep_samples(s);
  require_sweep(
      e.pre_onset_s + e.impulse_length_s < out.harmonic2_lead_s,
      "the 2nd harmonic's product lies " + std::to_string(out.harmonic2_lead_s) +
          " s before the response, less than the impulse length and pre-onset part: make the "
          "sweep longer or its range narrower");
  require_sweep(length + pre < silence, "impulse length must be shorter than the silence");

  // Circular deconvolution by one sweep period: the recording of R back-to-back periods becomes R
  // copies of the impulse response, one per period, each preceded by its harmonics' products.
  model::numeric::RealFft fft(n, model::numeric::RealFft::Plans::forward_and_backward);
  std::fill(fft.real().begin(), fft.real().end(), 0.0);
  std::copy(played.begin(), played.begin() + static_cast<std::ptrdiff_t>(period),
            fft.real().begin());
  fft.forward();
  const std::vector<std::complex<double>> x(fft.spectrum().begin(), fft.spectrum().end());
  double max_power = 0.0;
  for (const auto& v : x) max_power = std::max(max_power, std::norm(v));
  require_sweep(max_power > 0, "played signal is silent");
  const double epsilon = e.regularisation * max_power;
  std::copy(recorded.begin(), recorded.begin() + static_cast<std::ptrdiff_t>(n),
            fft.real().begin());
  fft.forward();
  auto y = fft.spectrum();
  for (std::size_t k = 0; k < y.size(); ++k) y[k] *= std::conj(x[k]) / (std::norm(x[k]) + epsilon);
  fft.backward();
  std::vector<double> h(fft.real().begin(), fft.real().end());
  for (double& v : h) v /= static_cast<double>(n);

  // The first copy lies in the first silence: search only where its whole window fits.
  const std::size_t search_end = silence - length;
  std::size_t peak = 0;
  for (std::size_t i = 1; i < search_end; ++i)
    if (std::abs(h[i]) > std::abs(h[peak])) peak = i;
  require_sweep(std::abs(h[peak]) > 0, "the recording holds no response to the sweep");
  const std::size_t search = to_samples(kOnsetSearch_s, fs);
  std::size_t onset = peak;
  for (std::size_t i = peak > search ? peak - search : 0; i < peak; ++i) {
    if (std::abs(h[i]) >= e.onset_threshold * std::abs(h[peak])) {
      onset = i;
      break;
    }
  }
  out.peak_lag_samples = peak;
  out.delay_samples = onset;
  out.delay_s = static_cast<double>(onset) / fs;
  require_sweep(
      onset + length < silence,
      "delay of " + std::to_string(out.delay_s) +
          " s leaves too little of the silence for the impulse response: lengthen the silence");

  const std::vector<double> window = impulse_window(pre, length);
  std::vector<std::vector<double>> copies(repetitions, std::vector<double>(window.size()));
  for (std::size_t r = 0; r < repetitions; ++r) {
    // Circular: with a short delay the leading edge of the first copy wraps to the end.
    const std::size_t start = (onset + r * period + n - pre) % n;
    for (std::size_t i = 0; i < window.size(); ++i) copies[r][i] = window[i] * h[(start + i) % n];
  }
  out.impulse_response = copies[0];

  // The faded ends of the sweep excite their frequencies too weakly to trust.
  const double fade_ratio = std::pow(s.end_hz / s.start_hz, s.fade_s / s.duration_s);
  const double f_low = s.start_hz * fade_ratio, f_high = s.end_hz / fade_ratio;
  for (double f = f_low; f <= f_high; f *= std::exp2(1.0 / e.points_per_octave)) {
    const double omega = 2.0 * kPi * f / fs;
    std::vector<std::complex<double>> estimates(repetitions);
    std::complex<double> mean = 0.0;
    for (std::size_t r = 0; r < repetitions; ++r) {
      estimates[r] = dtft(copies[r], pre, omega);
      mean += estimates[r];
    }
    mean /= static_cast<double>(repetitions);
    out.response.frequencies_hz.push_back(f);
    out.response.values.push_back(mean);
    if (repetitions >= 2) {
      double spread = 0.0;
      for (const auto& v : estimates) spread += std::norm(v - mean);
      const double variance_of_mean = spread / static_cast<double>(repetitions * (repetitions - 1));
      const double snr_db =
          variance_of_mean > 0
              ? 10.0 * std::log10(std::max(std::norm(mean) / variance_of_mean, 1e-30))
              : kSnrCeiling_db;
      out.snr_db.push_back(std::min(kSnrCeiling_db, snr_db));
    }
  }
  return out;
}

}  // namespace nibrig::playback
