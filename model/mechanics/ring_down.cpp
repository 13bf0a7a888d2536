#include "model/mechanics/ring_down.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <random>
#include <complex>
#include <numeric>
#include <stdexcept>
#include <unsupported/Eigen/LevenbergMarquardt>
#include <unsupported/Eigen/NumericalDiff>

#include "model/mechanics/ring_down_uncertainty.hpp"
#include "model/modal/modal_oscillator.hpp"
#include "model/numeric/real_fft.hpp"

namespace nibrig::model::mechanics {
namespace {

double dot(const std::vector<double>& a, const std::vector<double>& b) {
  return std::inner_product(a.begin(), a.end(), b.begin(), 0.0);
}

// The amplitude factor that best maps `simulated` onto `measured` (least squares).
double best_gain(const std::vector<double>& measured, const std::vector<double>& simulated) {
  const double energy = dot(simulated, simulated);
  return energy > 0 ? dot(measured, simulated) / energy : 0.0;
}

std::size_t fft_size_for(std::size_t samples) {
  std::size_t n = 1;
  while (n < 2 * samples) n *= 2;  // room for a linear (not circular) cross-correlation
  return n;
}

// |FFT| of a trace zero-padded to the transform's size.
std::vector<double> magnitude_spectrum(numeric::RealFft& fft, const std::vector<double>& signal) {
  auto real = fft.real();
  std::fill(real.begin(), real.end(), 0.0);
  std::copy(signal.begin(), signal.end(), real.begin());
  fft.forward();
  std::vector<double> magnitude(fft.bins());
  for (std::size_t k = 0; k < magnitude.size(); ++k) magnitude[k] = std::abs(fft.spectrum()[k]);
  return magnitude;
}

double normalised_correlation(const std::vector<double>& a, const std::vector<double>& b) {
  const double norms = std::sqrt(dot(a, a) * dot(b, b));
  return norms > 0 ? dot(a, b) / norms : 0.0;
}

// The lag (s, ≥ 0) by which `released_at_zero` must be delayed to line up with `measured`: the
// peak of their cross-correlation, refined between samples by a parabola through its neighbours.
double release_time_by_correlation(numeric::RealFft& fft, const std::vector<double>& measured,
                                   const std::vector<double>& released_at_zero,
                                   double sample_rate) {
  const std::size_t n = fft.size();
  auto spectrum_of = [&](const std::vector<double>& signal) {
    auto real = fft.real();
    std::fill(real.begin(), real.end(), 0.0);
    std::copy(signal.begin(), signal.end(), real.begin());
    fft.forward();
    return std::vector<std::complex<double>>(fft.spectrum().begin(), fft.spectrum().end());
  };
  const auto m = spectrum_of(measured);
  const auto s = spectrum_of(released_at_zero);
  for (std::size_t k = 0; k < m.size(); ++k) fft.spectrum()[k] = m[k] * std::conj(s[k]);
  fft.backward();
  const auto correlation = fft.real();
  const std::size_t lags = std::min(measured.size(), n);
  std::size_t best = 0;
  for (std::size_t lag = 1; lag < lags; ++lag)
    if (correlation[lag] > correlation[best]) best = lag;
  double offset = 0.0;
  if (best > 0 && best + 1 < lags) {
    const double left = correlation[best - 1], centre = correlation[best],
                 right = correlation[best + 1];
    const double curvature = left - 2 * centre + right;
    if (curvature < 0) offset = 0.5 * (left - right) / curvature;
  }
  return (static_cast<double>(best) + offset) / sample_rate;
}

// Residuals measured − g·simulated over the whole trace for θ = (ln modulus ratio, ln λ,
// t_release).
struct RingDownResiduals {
  using Scalar = double;
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;
  using QRSolver = Eigen::ColPivHouseholderQR<JacobianType>;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };

  const modal::ModalModel* reference;
  const RingDownOptions* options;
  const io::AccelerationTrace* trace;
  int* evaluations;
  double release_time = 0.0;

  int inputs() const { return 2; }

  double stiffness_damping(const Eigen::VectorXd& theta) const {
    return std::exp(theta[1]) / (reference->omega.front() * std::exp(theta[0] / 2));
  }
  int values() const { return static_cast<int>(trace->acceleration_m_s2.size()); }

  std::vector<double> simulate(const Eigen::VectorXd& theta, double* gain) const {
    const RayleighDamping damping{options->mass_damping, stiffness_damping(theta)};
    const modal::ModalModel model = rescale_modulus(*reference, std::exp(theta[0]), damping);
    const auto& measured = trace->acceleration_m_s2;
    std::vector<double> simulated = simulate_release(model, options->preload, trace->sample_rate_hz,
                                                     measured.size(), release_time);
    ++*evaluations;
    *gain = options->fit_gain ? best_gain(measured, simulated) : 1.0;
    return simulated;
  }

  int operator()(const Eigen::VectorXd& theta, Eigen::VectorXd& residuals) const {
    double gain = 1.0;
    const std::vector<double> simulated = simulate(theta, &gain);
    const auto& measured = trace->acceleration_m_s2;
    for (std::size_t i = 0; i < measured.size(); ++i)
      residuals[static_cast<Eigen::Index>(i)] = measured[i] - gain * simulated[i];
    return 0;
  }
};

}  // namespace

std::vector<double> simulate_release(const modal::ModalModel& model, double preload,
                                     double sample_rate, std::size_t samples, double release_time) {
  if (model.size() == 0)
    throw std::invalid_argument("release simulation: the modal model has no modes");
  if (!(sample_rate > 0) || !std::isfinite(sample_rate))
    throw std::invalid_argument("release simulation: the sample rate must be positive");
  if (!std::isfinite(preload) || !std::isfinite(release_time) || release_time < 0)
    throw std::invalid_argument(
        "release simulation: preload and release time must be finite, release time >= 0");
  double compliance = 0.0;  // tip displacement per unit tip force, Σ b²/ω²
  for (std::size_t i = 0; i < model.size(); ++i)
    compliance += model.input[i] * model.input[i] / (model.omega[i] * model.omega[i]);
  if (!(compliance > 0))
    throw std::invalid_argument("release simulation: no mode moves the tip along its direction");
  const double force = preload / compliance;

  std::vector<double> acceleration(samples, 0.0);
  const double step = 1.0 / sample_rate;
  const auto first = static_cast<std::size_t>(std::ceil(release_time * sample_rate - 1e-12));
  if (first >= samples) return acceleration;
  const double lead_in =
      static_cast<double>(first) * step - release_time;  // release to first sample
  for (std::size_t i = 0; i < model.size(); ++i) {
    const double omega = model.omega[i], zeta = model.zeta[i];
    modal::ModeState state{model.input[i] * force / (omega * omega), 0.0};
    if (lead_in > 0) state = modal::mode_transition(omega, zeta, lead_in).apply(state);
    const modal::Transition transition = modal::mode_transition(omega, zeta, step);
    const double c = model.output[i];
    for (std::size_t k = first; k < samples; ++k) {
      acceleration[k] += c * modal::modal_acceleration(omega, zeta, state, 0.0);
      state = transition.apply(state);
    }
  }
  return acceleration;
}

modal::ModalModel rescale_modulus(const modal::ModalModel& reference, double modulus_ratio,
                                  const RayleighDamping& damping) {
  if (!(modulus_ratio > 0) || !std::isfinite(modulus_ratio))
    throw std::invalid_argument("modulus ratio must be positive and finite");
  modal::ModalModel scaled = reference;
  const double frequency_ratio = std::sqrt(modulus_ratio);
  for (std::size_t i = 0; i < scaled.size(); ++i) {
    scaled.omega[i] *= frequency_ratio;
    scaled.zeta[i] =
        modal::rayleigh_damping_ratio(scaled.omega[i], damping.mass, damping.stiffness);
  }
  return scaled;
}

RingDownFit fit_ring_down(const modal::ModalModel& reference, const RingDownOptions& options,
                          const io::AccelerationTrace& trace) {
  if (reference.size() == 0)
    throw std::invalid_argument("ring-down fit: the modal model has no modes");
  if (!(options.reference_modulus > 0))
    throw std::invalid_argument("ring-down fit: the reference modulus must be positive");
  if (!(options.preload != 0) || !std::isfinite(options.preload))
    throw std::invalid_argument("ring-down fit: the preload must be non-zero and finite");
  const auto& measured = trace.acceleration_m_s2;
  if (measured.size() < 16 || !(dot(measured, measured) > 0))
    throw std::invalid_argument("ring-down fit: the trace holds no signal");

  int evaluations = 0;
  RingDownResiduals residuals{&reference, &options, &trace, &evaluations};
  numeric::RealFft fft(fft_size_for(measured.size()),
                       numeric::RealFft::Plans::forward_and_backward);
  const std::vector<double> measured_magnitude = magnitude_spectrum(fft, measured);

  // 1. Modulus and first-mode damping ratio on a grid, scored on magnitude spectra. 5 % steps in
  //    modulus (2.5 % in frequency) resolve a line as narrow as ζ = 2.5 %; the damping grid is in ζ
  //    of the first mode so that it means the same at every modulus.
  Eigen::VectorXd theta(2);
  double best_score = -1.0;
  for (double log_ratio = std::log(0.02); log_ratio <= std::log(50.0);
       log_ratio += std::log(1.05)) {
    for (double zeta1 : {0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5}) {
      Eigen::VectorXd candidate(2);
      candidate << log_ratio, std::log(2 * zeta1);
      double gain = 1.0;
      const double score = normalised_correlation(
          measured_magnitude, magnitude_spectrum(fft, residuals.simulate(candidate, &gain)));
      if (score > best_score) best_score = score, theta = candidate;
    }
  }
  // 2. Release time: where the model released at t = 0 best lines up with the trace.
  {
    double gain = 1.0;
    const std::vector<double> at_zero = residuals.simulate(theta, &gain);
    residuals.release_time =
        release_time_by_correlation(fft, measured, at_zero, trace.sample_rate_hz);
  }
  // 3. Levenberg-Marquardt on modulus and damping; then the release time by a search within 20
  //    samples of its estimate, to a twentieth of a sample; then both once more.
  Eigen::NumericalDiff<RingDownResiduals> numerical(residuals);
  auto refine = [&] {
    Eigen::LevenbergMarquardt<Eigen::NumericalDiff<RingDownResiduals>> solver(numerical);
    solver.setMaxfev(400);
    solver.minimize(theta);
  };
  auto misfit_at = [&](double release) {
    numerical.release_time = release;
    Eigen::VectorXd r(numerical.values());
    numerical(theta, r);
    return r.squaredNorm();
  };
  const double step = 1.0 / trace.sample_rate_hz;
  double best_release = numerical.release_time, best_misfit = misfit_at(best_release);
  auto search_release = [&](double spacing, int points) {
    const double centre = best_release;
    for (int k = -points; k <= points; ++k) {
      const double release = std::max(0.0, centre + k * spacing);
      const double m = misfit_at(release);
      if (m < best_misfit) best_misfit = m, best_release = release;
    }
    numerical.release_time = best_release;
  };
  refine();
  search_release(step, 20);  // the correlation peak of a decaying step can sit a few samples off
  search_release(step / 20, 20);  // then to a twentieth of a sample
  refine();
  best_misfit = misfit_at(best_release);
  search_release(step / 20, 20);
  // 4. Gauss-Newton on modulus, damping, release time and gain together: the search leaves the
  //    release time on its grid of a twentieth of a sample, and the modulus, correlated with it,
  //    off its least-squares value by a few of its standard deviations on a clean trace
  //    (ring_down_uncertainty_test). A step is kept only when it lowers the misfit.
  auto misfit_of = [&](const Eigen::VectorXd& t, double release) {
    RingDownResiduals probe = residuals;
    probe.release_time = release;
    Eigen::VectorXd r(probe.values());
    probe(t, r);
    return r.squaredNorm();
  };
  double current = misfit_of(theta, best_release);
  for (int polish = 0; polish < 4; ++polish) {
    double gain = 1.0;
    residuals.release_time = best_release;
    residuals.simulate(theta, &gain);
    const double ratio = std::exp(theta[0]), lambda = residuals.stiffness_damping(theta);
    const RingDownLinearisation lin = linearise_ring_down(
        reference, options, trace, options.reference_modulus * ratio, lambda, best_release, gain);
    const Eigen::VectorXd delta = (lin.jacobian.transpose() * lin.jacobian)
                                      .ldlt()
                                      .solve(lin.jacobian.transpose() * lin.residual);
    if (!delta.allFinite()) break;
    Eigen::VectorXd candidate(2);
    candidate[0] = theta[0] + delta[0];
    candidate[1] = std::log(lambda * std::exp(delta[1]) * reference.omega.front() *
                            std::exp(candidate[0] / 2));
    const double release = std::max(0.0, best_release + delta[2]);
    const double m = misfit_of(candidate, release);
    if (!(m < current)) break;
    current = m, theta = candidate, best_release = release;
  }
  residuals.release_time = best_release;

  RingDownFit fit;
  fit.youngs_modulus = options.reference_modulus * std::exp(theta[0]);
  fit.rayleigh_stiffness = residuals.stiffness_damping(theta);
  fit.release_time = best_release;
  const std::vector<double> simulated = residuals.simulate(theta, &fit.gain);
  fit.fitted.resize(simulated.size());
  double misfit = 0.0;
  for (std::size_t i = 0; i < simulated.size(); ++i) {
    fit.fitted[i] = fit.gain * simulated[i];
    misfit += (measured[i] - fit.fitted[i]) * (measured[i] - fit.fitted[i]);
  }
  fit.relative_residual = std::sqrt(misfit / dot(measured, measured));
  const modal::ModalModel fitted = rescale_modulus(reference, std::exp(theta[0]),
                                                   {options.mass_damping, fit.rayleigh_stiffness});
  fit.first_mode_hz = fitted.omega.front() / (2 * M_PI);
  fit.first_mode_damping_ratio = fitted.zeta.front();
  fit.evaluations = evaluations;
  return fit;
}

void add_relative_noise(std::vector<double>& trace, double relative_rms, unsigned seed) {
  if (trace.empty()) return;
  double sum = 0.0;
  for (double a : trace) sum += a * a;
  const double rms = std::sqrt(sum / static_cast<double>(trace.size()));
  std::mt19937 generator(seed);
  std::normal_distribution<double> noise(0.0, relative_rms * rms);
  for (double& a : trace) a += noise(generator);
}

}  // namespace nibrig::model::mechanics
