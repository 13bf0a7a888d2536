// The exact step of one mode under a force that is linear between two samples: the per-mode
// constants (Φ, Γ₀, Γ₁) of x_{n+1} = Φ x_n + Γ₀ f_n + Γ₁ f_{n+1}, in closed form. A signal sampled
// at rate 1/h and joined by straight lines is then integrated with no discretisation error at all.
#pragma once

#include "model/modal/modal_oscillator.hpp"

namespace nibrig::model::modal {

struct LinearForcingStep {
  Transition transition;  // Φ = e^{hU}
  ModeState
      from_start;  // Γ₀: state at t+h from rest under the unit modal force 1 − s/h, s ∈ [0, h]
  ModeState from_end;  // Γ₁: the same under s/h

  ModeState advance(ModeState x, double start_force, double end_force) const {
    const ModeState free = transition.apply(x);
    return {free.displacement + from_start.displacement * start_force +
                from_end.displacement * end_force,
            free.velocity + from_start.velocity * start_force + from_end.velocity * end_force};
  }
};

// ω > 0, ζ ≥ 0, step > 0, all finite; not validated here.
LinearForcingStep make_linear_forcing_step(double omega, double zeta, double step);

}  // namespace nibrig::model::modal
