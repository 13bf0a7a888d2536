#include "model/modal/linear_forcing_step.hpp"

// Over one step, with f(t_n + s) = f_n (1 − s/h) + f_{n+1} s/h and r = h − s the lag,
//   x_{n+1} = Φ x_n + ∫_0^h e^{rU} (0,1)ᵀ [f_n r/h + f_{n+1} (1 − r/h)] dr.
// With e^{rU}(0,1)ᵀ = (g(r), g'(r)), I₀ = ∫_0^h g dr and I₁ = ∫_0^h r g dr (impulse-response
// moments), and ∫ g' w dr = g(h) w(h) − w' I₀ for a linear weight w (by parts, g(0) = 0):
//   Γ₀ = ( I₁/h,        g(h) − I₀/h )      weight r/h
//   Γ₁ = ( I₀ − I₁/h,   I₀/h        )      weight 1 − r/h
// For h → 0 these tend to (h²/3, h/2) and (h²/6, h/2), the trapezoid-like split of a free mass.

namespace nibrig::model::modal {

LinearForcingStep make_linear_forcing_step(double omega, double zeta, double step) {
  const double h = step;
  LinearForcingStep s;
  s.transition = mode_transition(omega, zeta, h);
  const double i0 = impulse_response_moment(omega, zeta, h, 0).real();
  const double i1 = impulse_response_moment(omega, zeta, h, 1).real();
  s.from_start = {i1 / h, s.transition.dv - i0 / h};
  s.from_end = {i0 - i1 / h, i0 / h};
  return s;
}

}  // namespace nibrig::model::modal
