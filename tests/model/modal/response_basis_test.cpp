// Appendix A.4 (superposition) and A.5 (scaling), and the precomputed basis built on them: the
// response to a sum of sinusoids is the sum of the responses, a scaled force scales the response,
// and a basis of unit sine/cosine responses synthesises any set of amplitudes and phases on its
// grid as the direct simulation would. All are exact identities of a linear integrator, so the
// tolerances are rounding: a few ulps of the largest term summed.
#include "model/modal/response_basis.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <numbers>
#include <vector>

#include "model/modal/frequency_response.hpp"
#include "model/modal/linear_forcing_integrator.hpp"
#include "model/modal/sinusoid_step.hpp"
#include "tests/model/modal/modal_test_constants.hpp"
#include "tests/model/modal/paper_damped_model.hpp"

namespace nibrig::model::modal {
namespace {

using test::kPi;
using test::kRate;

ModalModel model() { return test::paper_damped_model(); }

double peak(const std::vector<double>& x) {
  double p = 0.0;
  for (double v : x) p = std::max(p, std::abs(v));
  return p;
}

// Reproducible numbers in [0, 1) from a 64-bit LCG (Knuth's MMIX constants).
struct Lcg {
  std::uint64_t s;
  double operator()() {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(s >> 11) * 0x1.0p-53;
  }
};

TEST(Superposition, ResponseToASumIsTheSumOfResponses) {
  const ModalModel m = model();
  const std::vector<Sinusoid> parts = {{0.4, 17.0, 0.1}, {0.9, 233.0, 2.0}, {0.2, 499.0, -1.3}};
  const std::size_t n = 3000;
  const std::vector<double> together = simulate_sinusoids(m, parts, kRate, n);
  std::vector<double> summed(n, 0.0);
  double scale = 0.0;
  for (const Sinusoid& p : parts) {
    const std::vector<double> one = simulate_sinusoids(m, {&p, 1}, kRate, n);
    for (std::size_t i = 0; i < n; ++i) summed[i] += one[i];
    scale += peak(one);
  }
  for (std::size_t i = 0; i < n; ++i) ASSERT_NEAR(together[i], summed[i], 1e-13 * scale) << i;

  // The same for the piecewise-linear engine on two arbitrary forces.
  Lcg rng{3};
  std::vector<double> f1(n), f2(n), f12(n), a1(n), a2(n), a12(n);
  for (std::size_t i = 0; i < n; ++i) {
    f1[i] = rng() - 0.5;
    f2[i] = 2.0 * std::sin(0.01 * static_cast<double>(i));
    f12[i] = f1[i] + f2[i];
  }
  LinearForcingIntegrator e(m, kRate);
  e.process(f1.data(), a1.data(), n);
  e.reset();
  e.process(f2.data(), a2.data(), n);
  e.reset();
  e.process(f12.data(), a12.data(), n);
  const double s = peak(a1) + peak(a2);
  for (std::size_t i = 0; i < n; ++i) ASSERT_NEAR(a12[i], a1[i] + a2[i], 1e-13 * s) << i;
}

TEST(Superposition, ScaledForceScalesTheResponse) {
  const ModalModel m = model();
  const std::size_t n = 2000;
  const Sinusoid unit{1.0, 311.0, 0.7};
  const std::vector<double> base = simulate_sinusoids(m, {&unit, 1}, kRate, n);
  for (double k : {-3.5, 1e-6, 250.0}) {
    const Sinusoid scaled{k, unit.frequency, unit.phase};
    const std::vector<double> a = simulate_sinusoids(m, {&scaled, 1}, kRate, n);
    for (std::size_t i = 0; i < n; ++i)
      ASSERT_NEAR(a[i], k * base[i], 1e-14 * std::abs(k) * peak(base))
          << "k " << k << " sample " << i;
  }
}

TEST(ResponseBasis, RowsAreTheUnitSineAndCosineResponses) {
  const ModalModel m = model();
  const std::vector<double> grid = {3.0, 120.0, 450.0};
  const FrequencyResponseBasis basis(m, kRate, 1500, grid);
  ASSERT_EQ(basis.frequencies(), grid);
  for (std::size_t k = 0; k < grid.size(); ++k) {
    const Sinusoid sine{1.0, grid[k], 0.0}, cosine{1.0, grid[k], kPi / 2.0};
    const std::vector<double> s = simulate_sinusoids(m, {&sine, 1}, kRate, 1500);
    const std::vector<double> c = simulate_sinusoids(m, {&cosine, 1}, kRate, 1500);
    // One complex run against two real ones: the same arithmetic up to the rounding of π/2.
    const double tol = 1e-14 * (peak(s) + peak(c));
    for (std::size_t n = 0; n < s.size(); ++n) {
      ASSERT_NEAR(basis.sine_response(k)[n], s[n], tol) << grid[k] << " Hz sample " << n;
      ASSERT_NEAR(basis.cosine_response(k)[n], c[n], tol) << grid[k] << " Hz sample " << n;
    }
  }
}

TEST(ResponseBasis, SynthesisOnTheDefaultGridEqualsDirectSimulation) {
  // 500 sinusoids with random amplitudes and phases at 1…500 Hz: the scaled sum of basis rows and
  // the direct simulation of all 500 at once add the same exact terms in different orders, so they
  // agree to rounding of the sum of the 500 terms' sizes.
  const ModalModel m = model();
  const std::size_t n = 1200;
  const FrequencyResponseBasis basis(m, kRate, n);
  ASSERT_EQ(basis.frequencies().size(), 500u);
  Lcg rng{11};
  std::vector<double> amplitude(500), phase(500);
  std::vector<Sinusoid> sinusoids;
  double scale = 0.0;
  for (std::size_t k = 0; k < 500; ++k) {
    amplitude[k] = rng() * 0.1;
    phase[k] = (rng() - 0.5) * 2.0 * kPi;
    sinusoids.push_back({amplitude[k], basis.frequencies()[k], phase[k]});
    scale +=
        amplitude[k] * (peak({basis.sine_response(k).begin(), basis.sine_response(k).end()}) +
                        peak({basis.cosine_response(k).begin(), basis.cosine_response(k).end()}));
  }
  const std::vector<double> synthesized = basis.synthesize(amplitude, phase);
  const std::vector<double> direct = simulate_sinusoids(m, sinusoids, kRate, n);
  for (std::size_t i = 0; i < n; ++i) ASSERT_NEAR(synthesized[i], direct[i], 1e-13 * scale) << i;
}

TEST(ResponseBasis, SettlesOnTheClosedFormFrequencyResponse) {
  // After the transient (≥ 200 /s here: e^{−50} by 0.25 s) each row is the steady state of H(f):
  // cos response = Re(H e^{jΩt}), sine response = Im(H e^{jΩt}). The stepped simulation and the
  // closed-form H share no code. Tolerance: 1e-12 of |H| for the rounding of 12000 steps, plus an
  // absolute 1e-14·Σ|c b|: at low f, q̈ = −ω²q − 2ζωq̇ + b f subtracts terms of size |b f| that
  // nearly cancel (H(1 Hz) is 1e-4 of Σ|c b| here), each rounded to an ulp.
  const ModalModel m = model();
  const std::vector<double> grid = {1.0, 50.0, 90.0, 333.0, 500.0};
  const std::size_t n = 12000;
  const FrequencyResponseBasis basis(m, kRate, n, grid);
  const auto h = frequency_response(m, grid);
  double cb_abs = 0.0;
  for (std::size_t i = 0; i < m.size(); ++i) cb_abs += std::abs(m.output[i] * m.input[i]);
  for (std::size_t k = 0; k < grid.size(); ++k) {
    const double tol = 1e-12 * std::abs(h[k]) + 1e-14 * cb_abs;
    for (std::size_t i = n - 500; i < n; ++i) {
      const std::complex<double> steady = h[k] * std::polar(1.0, sample_phase(grid[k], kRate, i));
      ASSERT_NEAR(basis.cosine_response(k)[i], steady.real(), tol) << grid[k] << " Hz";
      ASSERT_NEAR(basis.sine_response(k)[i], steady.imag(), tol) << grid[k] << " Hz";
    }
  }
}

TEST(FrequencyResponse, DefaultGridAndLimits) {
  const std::vector<double> grid = default_frequency_grid();
  ASSERT_EQ(grid.size(), 500u);
  EXPECT_EQ(grid.front(), 1.0);
  EXPECT_EQ(grid.back(), 500.0);
  // The two limits of an acceleration response, from the formula's structure: H(0) = 0 (a static
  // force gives no acceleration) and H → Σ c_i b_i far above every mode (the mass line), with
  // |H − Σ c b| ≤ Σ |c b| (ω² + 2ζωΩ)/(Ω² − ω²) by the triangle inequality on
  // H − c b = −c b (ω² + 2jζωΩ)/(ω² − Ω² + 2jζωΩ).
  const ModalModel m = model();
  const double f_high = 1e8, w_high = 2.0 * kPi * f_high;
  double cb = 0.0, bound = 0.0;
  for (std::size_t i = 0; i < m.size(); ++i) {
    const double w = m.omega[i];
    cb += m.output[i] * m.input[i];
    bound += std::abs(m.output[i] * m.input[i]) * (w * w + 2.0 * m.zeta[i] * w * w_high) /
             (w_high * w_high - w * w);
  }
  const std::vector<double> probe = {0.0, f_high};
  const auto h = frequency_response(m, probe);
  EXPECT_EQ(h[0], std::complex<double>(0.0, 0.0));
  EXPECT_LE(std::abs(h[1] - cb), bound);
  EXPECT_LT(bound, 1e-2 * std::abs(cb));  // so that the check says something
  // Without a grid, the default one: entry k is f = k + 1 Hz.
  const auto h_default = frequency_response(m);
  ASSERT_EQ(h_default.size(), 500u);
  EXPECT_EQ(h_default[99], frequency_response(m, std::vector<double>{100.0})[0]);
}

}  // namespace
}  // namespace nibrig::model::modal
