// The modal integrators against the unreduced system they stand for: a 4-DOF mass-spring chain
// M ẍ + D ẋ + K x = e_tip f(t) with Rayleigh damping D = αM + λK, integrated as the full 8-state
// first-order system with Eigen's matrix exponential of the augmented generator (force generator
// states appended), and reduced to a ModalModel with Eigen's generalized eigensolver. The
// integrators must reproduce the acceleration of the observed DOF.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <numbers>
#include <unsupported/Eigen/MatrixFunctions>
#include <vector>

#include "model/modal/frequency_response.hpp"
#include "model/modal/linear_forcing_integrator.hpp"
#include "model/modal/sinusoid_step.hpp"
#include "tests/model/modal/modal_test_constants.hpp"

namespace nibrig::model::modal {
namespace {

using test::kPi;
using test::kRate;
constexpr int kDof = 4;
constexpr int kTip = 3;     // force at the free end (the nib)
constexpr int kSensor = 1;  // accelerometer one mass in

struct Chain {
  Eigen::MatrixXd mass, damping, stiffness;
  double alpha = 30.0, lambda = 1.25e-4;  // λ: modes above ~2.5 kHz are overdamped

  Chain() {
    const Eigen::Vector4d m(2e-3, 1.5e-3, 1e-3, 0.6e-3);  // kg
    const Eigen::Vector4d k(4e4, 9e4, 2e5, 3e5);  // N/m, k₀ to ground, kⱼ between j−1 and j
    mass = m.asDiagonal();
    stiffness = Eigen::MatrixXd::Zero(kDof, kDof);
    for (int j = 0; j < kDof; ++j) {
      stiffness(j, j) += k[j];
      if (j > 0) {
        stiffness(j - 1, j - 1) += k[j];
        stiffness(j - 1, j) -= k[j];
        stiffness(j, j - 1) -= k[j];
      }
    }
    damping = alpha * mass + lambda * stiffness;
  }

  ModalModel modal() const {
    // K φ = ω² M φ with φᵀMφ = 1 (Eigen normalises generalized eigenvectors that way).
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(stiffness, mass);
    ModalModel m;
    for (int i = 0; i < kDof; ++i) {
      const double w = std::sqrt(solver.eigenvalues()[i]);
      m.omega.push_back(w);
      m.zeta.push_back(rayleigh_damping_ratio(w, alpha, lambda));
      m.input.push_back(solver.eigenvectors()(kTip, i));
      m.output.push_back(solver.eigenvectors()(kSensor, i));
    }
    return m;
  }

  // Generator of [x, ẋ, extra…] with the force a linear combination of the extra states.
  Eigen::MatrixXd generator(int extra, const Eigen::RowVectorXd& force_of_extra) const {
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(2 * kDof + extra, 2 * kDof + extra);
    const Eigen::MatrixXd m_inv = mass.inverse();
    a.block(0, kDof, kDof, kDof) = Eigen::MatrixXd::Identity(kDof, kDof);
    a.block(kDof, 0, kDof, kDof) = -m_inv * stiffness;
    a.block(kDof, kDof, kDof, kDof) = -m_inv * damping;
    a.block(kDof, 2 * kDof, kDof, extra) = m_inv.col(kTip) * force_of_extra;
    return a;
  }

  // e^{G} for a generator over one step, computed by Eigen in long double on the balanced state
  // (ω_ref x, ẋ) with ω_ref² = ‖M⁻¹K‖: unbalanced, the position rows are 10⁸ times the velocity
  // rows and the scaling-and-squaring error, relative to that norm, would swamp the small entries.
  Eigen::MatrixXd exponential(const Eigen::MatrixXd& g) const {
    const double w_ref = std::sqrt((mass.inverse() * stiffness).norm());
    Eigen::VectorXd t = Eigen::VectorXd::Ones(g.rows());
    t.head(kDof).setConstant(w_ref);
    const Eigen::MatrixXd balanced = t.asDiagonal() * g * t.cwiseInverse().asDiagonal();
    using MatrixXld = Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>;
    const MatrixXld e = balanced.cast<long double>().exp();
    return t.cwiseInverse().asDiagonal() * e.cast<double>() * t.asDiagonal();
  }

  // ẍ at the sensor from the state and the force: M⁻¹(e_tip f − K x − D ẋ).
  double sensor_acceleration(const Eigen::VectorXd& state, double force) const {
    Eigen::VectorXd rhs = -stiffness * state.head(kDof) - damping * state.segment(kDof, kDof);
    rhs[kTip] += force;
    return mass.ldlt().solve(rhs)[kSensor];
  }
};

TEST(CoupledChain, ModesSpanEveryDampingRegime) {
  // The comparison below is only as strong as the modes it covers: at least one under- and one
  // overdamped mode.
  const ModalModel m = Chain().modal();
  EXPECT_LT(*std::min_element(m.zeta.begin(), m.zeta.end()), 1.0);
  EXPECT_GT(*std::max_element(m.zeta.begin(), m.zeta.end()), 1.0);
}

TEST(CoupledChain, SinusoidsMatchTheFullSystemExponential) {
  const Chain chain;
  const std::vector<Sinusoid> s = {{0.6, 120.0, 0.3}, {0.25, 410.0, -2.0}};
  // Extra states: per sinusoid (S, C) with S' = ΩC, C' = −ΩS, S(0) = A sin φ, C(0) = A cos φ, so
  // S(t) = A sin(Ωt + φ); the force is ΣS.
  const int extra = 2 * static_cast<int>(s.size());
  Eigen::RowVectorXd force_of_extra = Eigen::RowVectorXd::Zero(extra);
  for (int k = 0; k < static_cast<int>(s.size()); ++k) force_of_extra[2 * k] = 1.0;
  Eigen::MatrixXd a = chain.generator(extra, force_of_extra);
  Eigen::VectorXd state = Eigen::VectorXd::Zero(2 * kDof + extra);
  for (std::size_t k = 0; k < s.size(); ++k) {
    const int o = 2 * kDof + 2 * static_cast<int>(k);
    const double w = 2.0 * kPi * s[k].frequency;
    a(o, o + 1) = w;
    a(o + 1, o) = -w;
    state[o] = s[k].amplitude * std::sin(s[k].phase);
    state[o + 1] = s[k].amplitude * std::cos(s[k].phase);
  }
  const Eigen::MatrixXd step = chain.exponential(a / kRate);

  const std::size_t samples = 4800;
  const std::vector<double> modal = simulate_sinusoids(chain.modal(), s, kRate, samples);
  std::vector<double> full(samples);
  for (std::size_t n = 0; n < samples; ++n) {
    full[n] = chain.sensor_acceleration(state, force_of_extra * state.tail(extra));
    state = step * state;
  }
  // The reference's step matrix is rounded to double and applied 4800 times; its harmonic generator
  // blocks do not decay, so the few-ulp error of each product accumulates linearly: 4800 · ~4 eps
  // ≈ 4e-12 of the peak at most (7e-14 measured).
  const double peak = std::abs(*std::max_element(
      full.begin(), full.end(), [](double x, double y) { return std::abs(x) < std::abs(y); }));
  for (std::size_t n = 0; n < samples; ++n)
    ASSERT_NEAR(modal[n], full[n], 5e-12 * peak) << "sample " << n;
}

TEST(CoupledChain, PiecewiseLinearForceMatchesTheFullSystemExponential) {
  // Extra states (f, f') with f'' = 0: one exponential of the generator over h integrates a force
  // that is linear within the step, exactly as the modal step assumes; per step f and f' are set
  // from the two samples.
  const Chain chain;
  Eigen::RowVectorXd force_of_extra(2);
  force_of_extra << 1.0, 0.0;
  Eigen::MatrixXd a = chain.generator(2, force_of_extra);
  a(2 * kDof, 2 * kDof + 1) = 1.0;
  const Eigen::MatrixXd step = chain.exponential(a / kRate);

  std::vector<double> force(4800);
  std::uint64_t s = 99;
  for (auto& f : force) {  // LCG noise (Knuth's MMIX constants), plus a steady push
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    f = 0.3 + static_cast<double>(s >> 11) * 0x1.0p-53 - 0.5;
  }
  LinearForcingIntegrator integrator(chain.modal(), kRate);
  std::vector<double> modal(force.size());
  integrator.process(force.data(), modal.data(), force.size());

  Eigen::VectorXd state = Eigen::VectorXd::Zero(2 * kDof + 2);
  double peak = 0.0;
  std::vector<double> full(force.size());
  for (std::size_t n = 0; n < force.size(); ++n) {
    if (n > 0) {
      state[2 * kDof] = force[n - 1];
      state[2 * kDof + 1] = (force[n] - force[n - 1]) * kRate;
      state = step * state;
    }
    full[n] = chain.sensor_acceleration(state, force[n]);
    peak = std::max(peak, std::abs(full[n]));
  }
  // Here every step restarts the force states, so only the damped modes carry rounding on, for
  // ≲ 1/(ζωh) ≈ 110 steps (the lightest mode): ~110 · 4 eps ≈ 1e-13 of the peak (2e-14 measured).
  for (std::size_t n = 0; n < force.size(); ++n)
    ASSERT_NEAR(modal[n], full[n], 5e-13 * peak) << "sample " << n;
}

TEST(CoupledChain, FrequencyResponseIsTheFullSystemsSteadyState) {
  // H(f) from the modal sum against the direct solve (K − Ω²M + jΩD) X = e_tip, a = −Ω² X_sensor:
  // two different computations of the same closed form; 1e-12 relative for the conditioning of a
  // 4×4 solve.
  const Chain chain;
  const std::vector<double> freqs = {1.0, 57.0, 250.0, 499.0, 1500.0, 7000.0};
  const auto h = frequency_response(chain.modal(), freqs);
  for (std::size_t k = 0; k < freqs.size(); ++k) {
    const double w = 2.0 * kPi * freqs[k];
    const Eigen::MatrixXcd dynamic =
        chain.stiffness.cast<std::complex<double>>() -
        w * w * chain.mass.cast<std::complex<double>>() +
        std::complex<double>(0.0, w) * chain.damping.cast<std::complex<double>>();
    Eigen::VectorXcd e = Eigen::VectorXcd::Zero(kDof);
    e[kTip] = 1.0;
    const std::complex<double> expected = -w * w * dynamic.partialPivLu().solve(e)[kSensor];
    EXPECT_NEAR(std::abs(h[k] - expected), 0.0, 1e-12 * std::abs(expected)) << freqs[k] << " Hz";
  }
}

}  // namespace
}  // namespace nibrig::model::modal
