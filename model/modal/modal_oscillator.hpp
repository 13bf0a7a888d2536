// The exact motion of one mode over one time step h: its 2×2 state transition e^{hU} and the
// integrals of its impulse response against the forcing shapes the integrators use (polynomial
// ramps, complex exponentials). The sinusoid and piecewise-linear steps are built from these alone.
#pragma once

#include <complex>

namespace nibrig::model::modal {

// The state of one mode: modal displacement q and velocity q̇ (units of the ModalModel's modes).
struct ModeState {
  double displacement = 0.0;
  double velocity = 0.0;
};

// e^{hU} for U = [[0, 1], [−ω², −2ζω]] acting on (q, q̇), row-major.
struct Transition {
  double dd = 1.0, dv = 0.0;  // q(t+h)  = dd·q + dv·q̇
  double vd = 0.0, vv = 1.0;  // q̇(t+h) = vd·q + vv·q̇

  ModeState apply(ModeState x) const {
    return {dd * x.displacement + dv * x.velocity, vd * x.displacement + vv * x.velocity};
  }
};

// The exact transition of the free mode q̈ + 2ζωq̇ + ω²q = 0 over `step` seconds. Valid for every
// ζ ≥ 0 (under-, critically and over-damped) without cancellation near ζ = 1, and for large ωh
// (a mode that decays within the step gives entries that underflow to 0, never inf or NaN).
// Arguments are not validated here: ω > 0, ζ ≥ 0, step > 0, all finite.
Transition mode_transition(double omega, double zeta, double step);

// ∫_0^h r^power g(r) e^{jΩr} dr, power 0 or 1, where g is the mode's displacement impulse response
// (g'' + 2ζωg' + ω²g = 0, g(0) = 0, g'(0) = 1), so that e^{rU}(0, 1)ᵀ = (g(r), g'(r)). Every
// forcing integral of Eq. 8 over one step reduces to these moments. Closed forms, no quadrature:
// where the poles are close (|μ|h ≤ 1, μ² = ω²(ζ²−1)) a series in μ²h² of incomplete-gamma terms,
// elsewhere integration-by-parts identities or the two poles' exponentials, whichever does not
// cancel. Relative error a few ulps times max(1, Ωh, min(ωh, 1/ζ)) (the rounding of the phases
// themselves), also at exact resonance of an undamped mode. Throws std::invalid_argument for
// another power; other arguments are not validated (ω > 0, ζ ≥ 0, step > 0, all finite).
std::complex<double> impulse_response_moment(double omega, double zeta, double step, int power,
                                             double forcing_omega = 0.0);

// The analytic acceleration of Appendix A.3: q̈ = −ω²q − 2ζωq̇ + f, f the modal force b·f_tip.
inline double modal_acceleration(double omega, double zeta, ModeState x, double modal_force) {
  return -omega * omega * x.displacement - 2.0 * zeta * omega * x.velocity + modal_force;
}

}  // namespace nibrig::model::modal
