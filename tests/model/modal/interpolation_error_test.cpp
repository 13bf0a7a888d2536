// The piecewise-linear step integrates the sampled force joined by straight lines exactly, so the
// only difference from the exact sinusoid integrator is the interpolation of the force itself. That
// difference is predicted here in closed form and compared sample by sample.
//
// Derivation. Let f(t) = A sin(Ωt + φ), Ω = 2πf₀, sampled at t_n = nT, T = 1/f_s, r = f₀/f_s.
// Joining samples by straight lines is f_L(t) = Σ_n f(nT) Λ(t/T − n) with the hat Λ(u) = max(0, 1 −
// |u|), i.e. f_L = (f · Ш_T) ∗ Λ(·/T). In the frequency domain Ш_T becomes f_s·Ш_{f_s} and Λ(t/T)
// becomes T·sinc²(νT) (sinc x = sin πx / πx), so F_L(ν) = sinc²(ν/f_s) Σ_k F(ν − k f_s): each line
// of f at ±f₀ is copied to ±f₀ + k f_s and weighted by sinc² there. Pairing the line at f₀ + k f_s
// with its mirror at −f₀ − k f_s,
//     f_L(t) = A Σ_{k∈ℤ} sinc²(r + k) sin((Ω + 2πk f_s) t + φ)                         (1)
// (check: at t = nT every term is sin(ΩnT + φ), and Σ_k sinc²(r + k) = 1, so f_L(nT) = f(nT)).
// The k = 0 term is the original sinusoid attenuated by sinc²(r); the k ≠ 0 terms are images above
// the audio band. A linear system answers A sin(νt + φ), for any real ν, with A·Im(H(ν)
// e^{j(νt+φ)}), H(−ν) = conj H(ν), H the force-to-acceleration response. Sampled at t = nT, an
// image's phasor e^{j(Ω + 2πk f_s)nT} equals e^{jΩnT}: every image aliases onto f₀. So in steady
// state
//     a_L(nT) − a(nT) = A Im(e^{j(ΩnT+φ)} E),  E = Σ_{k≠0} sinc²(r+k) H(f₀+kf_s) − (1 − sinc²(r))
//     H(f₀).
// With Σ_{k≠0} sinc²(r + k) = 1 − sinc²(r) this gives the bound
//     |a_L − a| ≤ A (1 − sinc²(r)) (|H(f₀)| + sup_{|ν| ≥ f_s − f₀} |H(ν)|),                  (2)
// second order in f₀/f_s: 1 − sinc²(r) ≈ (πr)²/3 = 3.6e-4 at 500 Hz / 48 kHz. (A zero-order hold
// would weight the lines with sinc(r) e^{−jπr} instead: an error ≈ πr, first order, 30× larger.)
// At low f₀ the images dominate: H(f₀) → 0 like f₀² while H(ν) → Σ c_i b_i above every mode, so the
// error relative to the signal grows toward low frequencies although its size falls like r².
//
// For the numbers, E is summed over |k| ≤ K with H − H∞ (H∞ = Σ c_i b_i, whose images sum exactly
// to (1 − sinc²(r)) H∞), and the rest is bounded: for |ν| ≥ 2·max ω_i, |H(ν) − H∞| ≤ Σ|c_i b_i|
// (ω_i² + 2ζ_iω_i|ν|) / (0.75 ν²), and sinc²(r + k) ≤ sin²(πr) / (π²(|k| − 1)²).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "model/modal/linear_forcing_integrator.hpp"
#include "model/modal/linear_forcing_step.hpp"
#include "model/modal/sinusoid_step.hpp"
#include "tests/model/modal/modal_test_constants.hpp"
#include "tests/model/modal/paper_damped_model.hpp"

namespace nibrig::model::modal {
namespace {

using test::kPi;
using test::kRate;

using test::paper_damped_model;

// H(ν) = Σ c b (−Ω²)/(ω² − Ω² + 2jζωΩ), Ω = 2πν, for any real ν (negative gives the conjugate).
std::complex<double> response(const ModalModel& m, double nu) {
  const double w_f = 2.0 * kPi * nu;
  std::complex<double> h = 0.0;
  for (std::size_t i = 0; i < m.size(); ++i) {
    const double w = m.omega[i];
    h += m.output[i] * m.input[i] * (-w_f * w_f) /
         std::complex<double>((w - w_f) * (w + w_f), 2.0 * m.zeta[i] * w * w_f);
  }
  return h;
}

double sinc2(double x) {
  if (x == 0.0) return 1.0;
  const double s = std::sin(kPi * x) / (kPi * x);
  return s * s;
}

struct Prediction {
  std::complex<double> error;  // E
  double tail;                 // bound on |E − (the summed part)|
  double bound;                // the right-hand side of (2) without A
};

Prediction predict(const ModalModel& m, double f0) {
  const double r = f0 / kRate;
  double cb = 0.0, cb_abs = 0.0, w_max = 0.0;
  for (std::size_t i = 0; i < m.size(); ++i) {
    cb += m.output[i] * m.input[i];
    cb_abs += std::abs(m.output[i] * m.input[i]);
    w_max = std::max(w_max, m.omega[i]);
  }
  const int K = 4000;
  std::complex<double> images = 0.0;
  for (int k = -K; k <= K; ++k) {
    if (k != 0) images += sinc2(r + k) * (response(m, f0 + k * kRate) - cb);
  }
  Prediction p;
  p.error = images - (1.0 - sinc2(r)) * (response(m, f0) - cb);
  // Tail |k| > K, both signs: ν_k ≥ 2π(|k| − 1) f_s ≥ 2 ω_max, Σ_{k>K} (k−1)^{−p} ≤
  // 1/((p−1)(K−2)^{p−1}).
  double tail = 0.0;
  for (std::size_t i = 0; i < m.size(); ++i) {
    const double w = m.omega[i], cbi = std::abs(m.output[i] * m.input[i]);
    const double nu_unit = 2.0 * kPi * kRate;  // ν_k ≥ nu_unit · (k − 1)
    tail += cbi * (w * w / (0.75 * nu_unit * nu_unit) / (3.0 * std::pow(K - 2.0, 3)) +
                   2.0 * m.zeta[i] * w / (0.75 * nu_unit) / (2.0 * std::pow(K - 2.0, 2)));
  }
  EXPECT_GT(2.0 * kPi * (K - 1) * kRate, 2.0 * w_max);
  p.tail = 2.0 * std::pow(std::sin(kPi * r) / kPi, 2) * tail;
  // sup |H| over |ν| ≥ f_s − f₀: every mode is far below (f_s − f₀)/√2, where ν²/|D| decreases in
  // ν.
  const double nu_min = 2.0 * kPi * (kRate - f0);
  double h_sup = 0.0;
  for (std::size_t i = 0; i < m.size(); ++i) {
    EXPECT_LT(m.omega[i] * std::sqrt(2.0), nu_min);
    h_sup += std::abs(m.output[i] * m.input[i]) * nu_min * nu_min /
             (nu_min * nu_min - m.omega[i] * m.omega[i]);
  }
  p.bound = (1.0 - sinc2(r)) * (std::abs(response(m, f0)) + h_sup);
  (void)cb_abs;
  return p;
}

// 0.25 s: the transients of both runs (and of their difference) decay at ≥ 200 /s, to e^{−40} of
// their start by 0.2 s; the comparison uses the last 0.05 s.
constexpr std::size_t kSamples = 12000;
constexpr std::size_t kCompareFrom = 9600;

std::vector<double> sampled_force(double amplitude, double f0, double phase) {
  std::vector<double> f(kSamples);
  for (std::size_t n = 0; n < kSamples; ++n)
    f[n] = amplitude * std::sin(sample_phase(f0, kRate, n) + phase);
  return f;
}

// Largest |measured − predicted| over the compared samples, and the largest |measured|.
std::pair<double, double> compare(const std::vector<double>& approx,
                                  const std::vector<double>& exact, double amplitude, double f0,
                                  double phase, std::complex<double> e) {
  double worst = 0.0, largest = 0.0;
  for (std::size_t n = kCompareFrom; n < kSamples; ++n) {
    const double predicted =
        amplitude * (std::polar(1.0, sample_phase(f0, kRate, n) + phase) * e).imag();
    const double measured = approx[n] - exact[n];
    worst = std::max(worst, std::abs(measured - predicted));
    largest = std::max(largest, std::abs(measured));
  }
  return {worst, largest};
}

// Both outputs are sums of terms of size up to ~A·Σ|c_i b_i| (the quasi-static −ω²q cancels b f at
// low frequency), each rounded to a few ulps: an absolute floor of 1e-13·A·Σ|c b| on top of the
// 1e-4·|E| allowed for the prediction itself (the truncated image sum is bounded separately).
double tolerance(const ModalModel& m, double amplitude, const Prediction& p) {
  double cb_abs = 0.0;
  for (std::size_t i = 0; i < m.size(); ++i) cb_abs += std::abs(m.output[i] * m.input[i]);
  return amplitude * (1e-4 * std::abs(p.error) + p.tail + 1e-13 * cb_abs);
}

TEST(InterpolationError, LinearStepDiffersFromExactSinusoidByThePredictedAmount) {
  const ModalModel m = paper_damped_model();
  const double amplitude = 0.7, phase = 0.4;
  LinearForcingIntegrator linear(m, kRate);
  std::vector<double> a_linear(kSamples);
  for (int f = 1; f <= 500; ++f) {
    const double f0 = f;
    const Prediction p = predict(m, f0);
    const Sinusoid s{amplitude, f0, phase};
    const std::vector<double> exact = simulate_sinusoids(m, {&s, 1}, kRate, kSamples);
    const std::vector<double> force = sampled_force(amplitude, f0, phase);
    linear.reset();
    linear.process(force.data(), a_linear.data(), kSamples);
    const auto [worst, largest] = compare(a_linear, exact, amplitude, f0, phase, p.error);
    SCOPED_TRACE(::testing::Message() << f0 << " Hz, |E| = " << std::abs(p.error));
    ASSERT_LE(worst, tolerance(m, amplitude, p));  // the measured error is the predicted one
    ASSERT_LE(largest, amplitude * p.bound);       // and within the bound (2)
  }
}

TEST(InterpolationError, ZeroOrderHoldWouldFailTheSameComparison) {
  // The check above must be able to fail: a zero-order-hold step (force held at f_n over the step,
  // x_{n+1} = Φx_n + (Γ₀ + Γ₁) b f_n) run through the same comparison misses the prediction by far
  // more than its tolerance.
  const ModalModel m = paper_damped_model();
  const double amplitude = 0.7, phase = 0.4;
  for (double f0 : {5.0, 100.0, 500.0}) {
    const Prediction p = predict(m, f0);
    const Sinusoid s{amplitude, f0, phase};
    const std::vector<double> exact = simulate_sinusoids(m, {&s, 1}, kRate, kSamples);
    const std::vector<double> force = sampled_force(amplitude, f0, phase);
    std::vector<double> a_zoh(kSamples, 0.0);
    std::vector<ModeState> x(m.size());
    for (std::size_t n = 0; n < kSamples; ++n) {
      for (std::size_t i = 0; i < m.size(); ++i) {
        const LinearForcingStep st = make_linear_forcing_step(m.omega[i], m.zeta[i], 1.0 / kRate);
        if (n > 0) {
          const double held = m.input[i] * force[n - 1];
          x[i] = st.advance(x[i], held, held);
        }
        a_zoh[n] +=
            m.output[i] * modal_acceleration(m.omega[i], m.zeta[i], x[i], m.input[i] * force[n]);
      }
    }
    const auto [worst, largest] = compare(a_zoh, exact, amplitude, f0, phase, p.error);
    EXPECT_GT(worst, 10.0 * tolerance(m, amplitude, p)) << f0 << " Hz";
    EXPECT_GT(largest, amplitude * p.bound) << f0 << " Hz";
  }
}

}  // namespace
}  // namespace nibrig::model::modal
