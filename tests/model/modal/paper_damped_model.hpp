// A stylus-like modal model shared by the integrator tests: five modes with the paper's stiffness
// damping λ = 1.25e-3 s (ζ = λω/2): one light mode, one near critical, the rest overdamped. Every
// transient decays at ≥ 200 /s (the 90 Hz mode).
#pragma once

#include <numbers>

#include "model/modal/modal_model.hpp"

namespace nibrig::model::modal::test {

inline ModalModel paper_damped_model() {
  ModalModel m;
  for (double f : {90.0, 240.0, 620.0, 2400.0, 7000.0}) {
    const double w = 2.0 * std::numbers::pi * f;
    m.omega.push_back(w);
    m.zeta.push_back(rayleigh_damping_ratio(w, 0.0, 1.25e-3));
  }
  m.input = {1.1, -0.8, 0.5, 0.9, -0.4};
  m.output = {0.7, 1.3, -0.6, 0.35, 0.8};
  return m;
}

}  // namespace nibrig::model::modal::test
