// The frequency response of the modal model as LinearForcingIntegrator runs it at a given rate:
// from force samples to sensor-acceleration samples, with the straight-line joins between force
// samples and the aliasing of sampling included. It tends to the continuous H(f) as the rate
// grows; at a few kHz it differs near the stylus's anti-resonances, where the joins' images around
// the sampling rate, seen through stiff high modes, fold back. A voice that must reproduce a
// spectrum divides by this one.
#pragma once

#include <complex>
#include <span>
#include <vector>

#include "model/modal/modal_model.hpp"

namespace nibrig::model::modal {

// H_d(e^{j2πf/fs}) of x_n = Φ x_{n−1} + b(Γ₀ f_{n−1} + Γ₁ f_n), a_n = Σ c(−ω² q_n − 2ζω q̇_n + b f_n),
// per mode in closed form (a 2×2 resolvent). Frequencies in Hz, 0 ≤ f ≤ fs/2. Throws
// std::invalid_argument for a bad model, rate or frequency.
std::vector<std::complex<double>> discrete_frequency_response(const ModalModel& model,
                                                              double sample_rate_hz,
                                                              std::span<const double> frequencies);

}  // namespace nibrig::model::modal
