#include "model/modal/linear_forcing_integrator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <vector>

#include "model/modal/linear_forcing_step.hpp"
#include "tests/model/modal/modal_test_constants.hpp"

namespace nibrig::model::modal {
namespace {

using test::kPi;
using test::kRate;

// Seven modes (not a multiple of the engine's four lanes, so padding is exercised) across the
// damping regimes of a stylus with the paper's λ = 1.25e-3 (ζ = λω/2) plus two light ones.
ModalModel stylus_like_model() {
  ModalModel m;
  const double lambda = 1.25e-3;
  for (double f : {95.0, 410.0, 1300.0, 2900.0, 6100.0, 11000.0, 19000.0}) {
    const double w = 2.0 * kPi * f;
    m.omega.push_back(w);
    m.zeta.push_back(rayleigh_damping_ratio(w, 0.0, lambda));
  }
  m.zeta[0] = 0.004;
  m.zeta[2] = 1.0;  // exactly critical
  m.input = {0.9, -1.4, 0.6, 1.1, -0.3, 0.8, 0.5};
  m.output = {1.2, 0.7, -0.9, 0.4, 1.3, -0.6, 0.2};
  return m;
}

// A reproducible force: LCG noise (Knuth's MMIX constants), ±2 N, values exact in float.
std::vector<double> noise_force(std::size_t n) {
  std::vector<double> f(n);
  std::uint64_t s = 12345;
  for (auto& x : f) {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    x = static_cast<double>(
        static_cast<float>(static_cast<double>(s >> 11) * 0x1.0p-53 * 4.0 - 2.0));
  }
  return f;
}

TEST(LinearForcingIntegrator, EngineIsThePerModeRecursion) {
  // The grouped, vectorised engine must compute exactly x_{n+1} = Φx_n + bΓ₀f_n + bΓ₁f_{n+1} and
  // a = Σ c(−ω²q − 2ζωq̇ + b f) per mode. Only the order of the sums differs, so the tolerance is
  // 1e-14 of the sum of the magnitudes of the terms.
  const ModalModel m = stylus_like_model();
  const std::vector<double> force = noise_force(3000);
  LinearForcingIntegrator engine(m, kRate);
  std::vector<double> a(force.size());
  engine.process(force.data(), a.data(), force.size());

  std::vector<LinearForcingStep> steps;
  for (std::size_t i = 0; i < m.size(); ++i)
    steps.push_back(make_linear_forcing_step(m.omega[i], m.zeta[i], 1.0 / kRate));
  std::vector<ModeState> x(m.size());
  for (std::size_t n = 0; n < force.size(); ++n) {
    double expected = 0.0, magnitude = 0.0;
    for (std::size_t i = 0; i < m.size(); ++i) {
      if (n > 0) x[i] = steps[i].advance(x[i], m.input[i] * force[n - 1], m.input[i] * force[n]);
      const double term =
          m.output[i] * modal_acceleration(m.omega[i], m.zeta[i], x[i], m.input[i] * force[n]);
      expected += term;
      magnitude += std::abs(m.output[i] * m.input[i] * force[n]) +
                   std::abs(m.output[i] * m.omega[i] * m.omega[i] * x[i].displacement);
    }
    ASSERT_NEAR(a[n], expected, 1e-14 * magnitude) << "sample " << n;
  }
  for (std::size_t i = 0; i < m.size(); ++i) {
    EXPECT_NEAR(engine.displacement(i), x[i].displacement, 1e-14 * std::abs(x[i].displacement));
  }
}

TEST(LinearForcingIntegrator, BlocksInPlaceFloatAndResetAllGiveTheSameSamples) {
  // The recursion carries its state and last force across calls, so any split into blocks, and
  // in-place processing, must give the bit-identical sequence. The float path converts exactly
  // (force values are floats) and runs in double, so it is the double result rounded once.
  const ModalModel m = stylus_like_model();
  const std::vector<double> force = noise_force(1000);
  LinearForcingIntegrator whole(m, kRate);
  std::vector<double> a(force.size());
  whole.process(force.data(), a.data(), force.size());

  LinearForcingIntegrator blocks(m, kRate);
  std::vector<double> b = force;  // processed in place
  std::size_t at = 0;
  for (std::size_t len : {1, 0, 63, 64, 200, 672}) {
    blocks.process(b.data() + at, b.data() + at, len);
    at += len;
  }
  ASSERT_EQ(at, force.size());
  for (std::size_t n = 0; n < force.size(); ++n) ASSERT_EQ(b[n], a[n]) << "sample " << n;

  LinearForcingIntegrator single(m, kRate);
  std::vector<float> ff(force.begin(), force.end()), af(force.size());
  single.process(ff.data(), af.data(), ff.size());
  for (std::size_t n = 0; n < force.size(); ++n)
    ASSERT_EQ(af[n], static_cast<float>(a[n])) << "sample " << n;

  whole.reset();
  std::vector<double> again(force.size());
  whole.process(force.data(), again.data(), force.size());
  EXPECT_EQ(again, a);
}

TEST(LinearForcingIntegrator, TheVectorKernelIsThePortableOneToRoundingOverAMinute) {
  // The AVX2 loop fuses each multiply-add (one rounding where the portable loop has two), so the
  // two differ by rounding only. In a stable recursion a rounding error decays at its mode's rate
  // instead of adding up: measured, the difference stays near 6e-15 of the signal's peak over the
  // whole minute; 1e-12 leaves a margin of 150 and fails for any loop that computes otherwise.
  LinearForcingIntegrator portable(stylus_like_model(), kRate);
  portable.set_kernel(LinearForcingIntegrator::Kernel::portable);
  LinearForcingIntegrator vector(stylus_like_model(), kRate);
  if (vector.kernel() != LinearForcingIntegrator::Kernel::avx2_fma)
    GTEST_SKIP() << "this CPU has no AVX2 and FMA: only the portable loop runs here";
  const std::vector<double> force = noise_force(static_cast<std::size_t>(60 * kRate));
  std::vector<double> a(force.size()), b(force.size());
  for (std::size_t at = 0; at < force.size(); at += 64) {
    const std::size_t n = std::min<std::size_t>(64, force.size() - at);
    portable.process(force.data() + at, a.data() + at, n);
    vector.process(force.data() + at, b.data() + at, n);
  }
  const auto ten_seconds = static_cast<std::size_t>(10 * kRate);
  double peak = 0.0, worst = 0.0, first = 0.0, last = 0.0;
  for (std::size_t n = 0; n < a.size(); ++n) {
    const double d = std::abs(a[n] - b[n]);
    peak = std::max(peak, std::abs(a[n]));
    worst = std::max(worst, d);
    if (n < ten_seconds) first = std::max(first, d);
    if (n >= a.size() - ten_seconds) last = std::max(last, d);
  }
  EXPECT_LE(worst, 1e-12 * peak) << "peak " << peak;
  EXPECT_GT(first, 0.0) << "the two loops should round differently (is the vector one running?)";
  // Stationary, not growing: the last ten seconds' worst within a factor 10 of the first ten's
  // (two maxima of the same rounding noise; a growing error would be thousands of times larger).
  EXPECT_LE(last, 10 * first);
}

TEST(LinearForcingIntegrator, FirstSampleIsTheTimeOriginAtRest) {
  // At rest only the instantaneous b·f part of q̈ reaches the sensor: a(0) = Σ c_i b_i f(0).
  const ModalModel m = stylus_like_model();
  LinearForcingIntegrator engine(m, kRate);
  double cb = 0.0;
  for (std::size_t i = 0; i < m.size(); ++i) cb += m.output[i] * m.input[i];
  const double f = 1.75;
  double a = 0.0;
  engine.process(&f, &a, 1);
  EXPECT_DOUBLE_EQ(a, cb * f);
}

TEST(LinearForcingIntegrator, StartedInEquilibriumTheQuasiStaticModesStayStillUnderAConstantForce) {
  // Of the seven modes only the 95 Hz one is resonant (ζ 0.004); 410 Hz and above are overdamped
  // (ζ = λω/2 ≥ 1) or critical. Held still at b·f/ω² under a constant f, those sit at their fixed
  // point for ever: the sensor reads what the resonant mode alone, started at rest, gives.
  const ModalModel m = stylus_like_model();
  ModalModel resonant;
  resonant.omega = {m.omega[0]};
  resonant.zeta = {m.zeta[0]};
  resonant.input = {m.input[0]};
  resonant.output = {m.output[0]};
  double cb = 0.0;
  for (std::size_t i = 0; i < m.size(); ++i) cb += m.output[i] * m.input[i];
  const double f = 1.75;
  std::vector<double> force(4800, f), a(4800), alone(4800);
  LinearForcingIntegrator held(m, kRate);
  held.set_start(LinearForcingIntegrator::Start::in_equilibrium);
  held.process(force.data(), a.data(), a.size());
  LinearForcingIntegrator reference(resonant, kRate);
  reference.process(force.data(), alone.data(), alone.size());
  for (std::size_t n = 0; n < a.size(); ++n) ASSERT_NEAR(a[n], alone[n], 1e-9 * std::abs(cb * f)) << n;
  // From rest the whole model starts at Σ c·b·f.
  LinearForcingIntegrator rest(m, kRate);
  rest.process(force.data(), a.data(), 1);
  EXPECT_DOUBLE_EQ(a[0], cb * f);
  // reset() keeps the start chosen.
  held.reset();
  held.process(force.data(), a.data(), 2);
  EXPECT_NEAR(a[1], alone[1], 1e-9 * std::abs(cb * f));
}

TEST(LinearForcingIntegrator, FreeVibrationEnergyDecaysAtTwiceZetaOmega) {
  // E = (q̇² + ω²q²)/2 of a free underdamped mode has the envelope e^{−2ζωt}; over one damped
  // period T_d = 2π/ω_d exactly, e^{T_dU} = e^{−ζωT_d}·I, so E(t + T_d) = e^{−2ζωT_d}E(t) for any
  // start. The sample rate makes T_d 160 samples (f_d = 300 Hz). Tolerance 1e-11 in ln E: ~1600
  // steps of a few ulps each, and ω_d recovered from ω and ζ within an ulp.
  const std::size_t per_period = 160;
  const double omega_d = 2.0 * kPi * kRate / static_cast<double>(per_period);
  ModalModel m;
  for (double zeta : {0.01, 0.2, 0.9}) {
    m.omega.push_back(omega_d / std::sqrt((1.0 - zeta) * (1.0 + zeta)));
    m.zeta.push_back(zeta);
    m.input.push_back(1.0);
    m.output.push_back(1.0);
  }
  LinearForcingIntegrator engine(m, kRate);
  const std::vector<double> q0 = {1e-3, -2e-4, 5e-4}, v0 = {0.0, 3.0, -1.0};
  engine.set_state(q0, v0, 0.0);
  auto energy = [&](std::size_t i, double q, double v) {
    return 0.5 * (v * v + m.omega[i] * m.omega[i] * q * q);
  };
  std::vector<double> zeros(per_period, 0.0), out(per_period);
  const double period = 2.0 * kPi / omega_d;
  for (int k = 1; k <= 10; ++k) {
    engine.process(zeros.data(), out.data(), per_period);
    for (std::size_t i = 0; i < m.size(); ++i) {
      const double ratio =
          energy(i, engine.displacement(i), engine.velocity(i)) / energy(i, q0[i], v0[i]);
      EXPECT_NEAR(std::log(ratio), -2.0 * m.zeta[i] * m.omega[i] * period * k, 1e-11)
          << "zeta " << m.zeta[i] << " period " << k;
    }
  }
}

TEST(LinearForcingIntegrator, FreeEnergyNeverGrowsAndIsKeptWithoutDamping) {
  // dE/dt = −2ζω q̇² ≤ 0 for every ζ, so E may not rise from one sample to the next beyond rounding
  // (1e-14 relative). With ζ = 0 it is conserved up to the rounding of Φ: its entries are an ulp
  // off a rotation, so each step scales E by 1 ± a few eps and 48000 steps drift by at most
  // ~4·48000·eps ≈ 4e-11 (1.9e-12 measured).
  ModalModel m;
  m.omega = {2.0 * kPi * 200.0, 2.0 * kPi * 200.0, 2.0 * kPi * 900.0, 2.0 * kPi * 5000.0};
  m.zeta = {0.0, 0.3, 1.0, 7.0};
  m.input = {1.0, 1.0, 1.0, 1.0};
  m.output = {1.0, 1.0, 1.0, 1.0};
  LinearForcingIntegrator engine(m, kRate);
  const std::vector<double> q0 = {1e-3, 1e-3, 1e-4, 1e-5}, v0 = {0.5, -0.5, 2.0, 3.0};
  engine.set_state(q0, v0, 0.0);
  std::vector<double> last(m.size());
  for (std::size_t i = 0; i < m.size(); ++i)
    last[i] = 0.5 * (v0[i] * v0[i] + m.omega[i] * m.omega[i] * q0[i] * q0[i]);
  const double e0 = last[0];
  const double zero = 0.0;
  double out = 0.0;
  for (int n = 0; n < 48000; ++n) {
    engine.process(&zero, &out, 1);
    for (std::size_t i = 0; i < m.size(); ++i) {
      const double q = engine.displacement(i), v = engine.velocity(i);
      const double e = 0.5 * (v * v + m.omega[i] * m.omega[i] * q * q);
      // Once q² is subnormal (E below ~1e-300) rounding is no longer relative: stop checking there.
      if (last[i] > 1e-280) {
        ASSERT_LE(e, last[i] * (1.0 + 1e-14)) << "mode " << i << " step " << n;
      }
      last[i] = e;
    }
  }
  EXPECT_NEAR(last[0] / e0, 1.0, 4.0 * 48000.0 * std::numeric_limits<double>::epsilon());
}

}  // namespace
}  // namespace nibrig::model::modal
