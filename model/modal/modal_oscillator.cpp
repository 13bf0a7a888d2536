#include "model/modal/modal_oscillator.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

// Notation. σ = ζω, μ² = σ² − ω² = ω²(ζ−1)(ζ+1) (negative when underdamped, exactly 0 at ζ = 1),
// poles s₁,₂ = −σ ± μ. Because (U + σI)² = μ²I (Cayley–Hamilton), the transition is
//   e^{hU} = e^{−σh} [ C(h) I + S(h) (U + σI) ],   C = cosh(μh),  S = sinh(μh)/μ,
// and C, S are entire functions of μ²h² (cos and sin(x)/x when μ² < 0): no division by s₁ − s₂,
// so nothing cancels as ζ → 1. The impulse response is g(r) = e^{−σr} S(r).
//
// Where the poles are far apart (|μ|h > 1) and the mode is overdamped, e^{−σh}cosh(μh) would be
// 0·∞ for large h; there the transition is written with the two real exponentials instead,
// e^{hU} = (e^{s₁h}(U − s₂I) − e^{s₂h}(U − s₁I)) / (2μ), with the slow pole's rate
// a = −s₁ = ω²/(σ+μ) (not σ − μ, which cancels) and b = −s₂ = σ + μ.

namespace nibrig::model::modal {
namespace {

using cplx = std::complex<double>;

struct Poles {
  double omega;
  double sigma;  // ζω
  double mu2;    // ω²(ζ−1)(ζ+1)
};

Poles poles(double omega, double zeta) {
  return {omega, zeta * omega, omega * omega * (zeta - 1.0) * (zeta + 1.0)};
}

// cosh(√y) and sinh(√y)/√y for real y of either sign.
double cosh_sqrt(double y) { return y >= 0.0 ? std::cosh(std::sqrt(y)) : std::cos(std::sqrt(-y)); }

double sinhc_sqrt(double y) {
  const double x = std::sqrt(std::abs(y));
  if (x == 0.0) return 1.0;
  // sin and sinh are accurate to an ulp relative to themselves near 0, so the quotient is too.
  return y > 0.0 ? std::sinh(x) / x : std::sin(x) / x;
}

bool far_apart_overdamped(const Poles& p, double h) { return p.mu2 > 0.0 && p.mu2 * h * h > 1.0; }

// J_n(z) = ∫_0^1 θⁿ e^{−zθ} dθ for Re z ≥ 0 (|J_n| ≤ 1/(n+1)).
//  · |z| ≤ n+1: J_n = e^{−z} Σ_j z^j / ((n+1)(n+2)…(n+1+j)), the series of the lower incomplete
//    gamma function γ(n+1, z)/z^{n+1}; the term ratio |z|/(n+1+j) < 1, so it converges without
//    growing terms.
//  · |z| > n+1: J_0 = (1 − e^{−z})/z and J_k = (k J_{k−1} − e^{−z})/z upward; each step multiplies
//    the inherited error by k/|z| < 1, so the recurrence is stable.
cplx theta_moment(int n, cplx z) {
  const double nn = static_cast<double>(n);
  if (std::abs(z) <= nn + 1.0) {
    cplx term = 1.0 / (nn + 1.0);
    cplx sum = term;
    for (int j = 1; j < 1000; ++j) {
      term *= z / (nn + 1.0 + static_cast<double>(j));
      sum += term;
      if (std::abs(term) <= 1e-18 * std::abs(sum)) break;
    }
    return std::exp(-z) * sum;
  }
  const cplx e = std::exp(-z);
  cplx j = (1.0 - e) / z;
  for (int k = 1; k <= n; ++k) j = (static_cast<double>(k) * j - e) / z;
  return j;
}

// ∫_0^h r^m g(r) e^{νr} dr with ν = jΩ, three closed forms chosen by where each is free of
// cancellation (see impulse_response_moment below for the identities).
cplx moment(const Poles& p, double h, int m, double forcing_omega, const Transition& phi) {
  const cplx nu(0.0, forcing_omega);
  const cplx sigma_shift(p.sigma, -forcing_omega);  // σ − ν
  const double y = p.mu2 * h * h;

  if (std::abs(y) <= 1.0) {
    // Poles close together (including ζ = 1 exactly and every small step): expand
    // S(r) = Σ_k μ^{2k} r^{2k+1}/(2k+1)!, so ∫ r^m e^{−(σ−ν)r} S(r) dr
    //      = h^{m+2} Σ_k (μ²h²)^k/(2k+1)! · J_{2k+1+m}((σ−ν)h).
    // |J| ≤ 1/(n+1) and |μ²h²| ≤ 1 bound term k by 1/(2k+1)!: 14 terms reach 1e-27.
    cplx sum = 0.0;
    double coefficient = 1.0;
    for (int k = 0; k < 14; ++k) {
      if (k > 0) coefficient *= y / (static_cast<double>(2 * k) * static_cast<double>(2 * k + 1));
      sum += coefficient * theta_moment(2 * k + 1 + m, sigma_shift * h);
    }
    return std::pow(h, m + 2) * sum;
  }

  // Poles apart. The integration-by-parts identities (from g'' + 2σg' + ω²g = 0):
  //   M₀ (ω² − 2σν + ν²) = 1 − w,                      w = e^{νh}(Φ_dd − νΦ_dv)
  //   M₁ (ω² − 2σν + ν²) = e^{νh}(Φ_dv − hΦ_dd + νhΦ_dv) + 2(σ − ν)M₀
  // are free of cancellation when the mode has moved well away from its start over the step
  // (|w| ≤ ½). Otherwise the slow pole barely decays within h and the difference of the two poles'
  // moments is the well-conditioned form:
  //   M_m = h^{m+1} (J_m((σ−ν−μ)h) − J_m((σ−ν+μ)h)) / (2μ).
  const cplx eh = std::polar(1.0, forcing_omega * h);
  const cplx w = eh * (phi.dd - nu * phi.dv);
  if (std::abs(w) <= 0.5) {
    // ω² − Ω² − 2jσΩ with ω² − Ω² factored so that it does not cancel near resonance.
    const cplx denominator((p.omega - forcing_omega) * (p.omega + forcing_omega),
                           -2.0 * p.sigma * forcing_omega);
    const cplx m0 = (1.0 - w) / denominator;
    if (m == 0) return m0;
    return (eh * (phi.dv - h * phi.dd + nu * h * phi.dv) + 2.0 * sigma_shift * m0) / denominator;
  }
  cplx slow, fast, two_mu;
  if (p.mu2 > 0.0) {
    const double mu = std::sqrt(p.mu2);
    slow = cplx(p.omega * p.omega / (p.sigma + mu), -forcing_omega) * h;  // (σ − μ − ν)h
    fast = cplx(p.sigma + mu, -forcing_omega) * h;
    two_mu = 2.0 * mu;
  } else {
    const double omega_d = std::sqrt(-p.mu2);  // μ = jω_d
    slow = cplx(p.sigma, -forcing_omega - omega_d) * h;
    fast = cplx(p.sigma, -forcing_omega + omega_d) * h;
    two_mu = cplx(0.0, 2.0 * omega_d);
  }
  return std::pow(h, m + 1) * (theta_moment(m, slow) - theta_moment(m, fast)) / two_mu;
}

}  // namespace

Transition mode_transition(double omega, double zeta, double step) {
  const Poles p = poles(omega, zeta);
  const double h = step;
  if (far_apart_overdamped(p, h)) {
    const double mu = std::sqrt(p.mu2);
    const double a = omega * omega / (p.sigma + mu);
    const double b = p.sigma + mu;
    const double ea = std::exp(-a * h);
    const double eb = std::exp(-b * h);
    const double dv = (ea - eb) / (2.0 * mu);  // μh > 1: e^{−bh} ≤ e^{−2}e^{−ah}, no cancellation
    return {(b * ea - a * eb) / (2.0 * mu), dv, -omega * omega * dv,
            (b * eb - a * ea) / (2.0 * mu)};
  }
  const double y = p.mu2 * h * h;
  const double decay = std::exp(-p.sigma * h);
  const double c = decay * cosh_sqrt(y);
  const double s = decay * h * sinhc_sqrt(y);
  return {c + p.sigma * s, s, -omega * omega * s, c - p.sigma * s};
}

std::complex<double> impulse_response_moment(double omega, double zeta, double step, int power,
                                             double forcing_omega) {
  if (power != 0 && power != 1) {
    throw std::invalid_argument("impulse_response_moment: power must be 0 or 1, got " +
                                std::to_string(power));
  }
  const Poles p = poles(omega, zeta);
  return moment(p, step, power, forcing_omega, mode_transition(omega, zeta, step));
}

}  // namespace nibrig::model::modal
