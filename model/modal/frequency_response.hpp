// The tool's frequency response from tip force to sensor acceleration in closed form (the steady
// state of every mode under a sinusoid), and the default forcing-frequency grid of the paper's
// forcing model (1-500 Hz every 1 Hz), shared by the response basis and the forcing fit.
#pragma once

#include <complex>
#include <span>
#include <vector>

#include "model/modal/modal_model.hpp"

namespace nibrig::model::modal {

// 1, 2, …, 500 Hz.
std::vector<double> default_frequency_grid();

// H(f) = Σ_i c_i b_i (−Ω²) / (ω_i² − Ω² + 2jζ_iω_iΩ), Ω = 2πf, in (m/s²)/N: the steady-state
// acceleration is Re/Im of H(f)·A·e^{j(Ωt+φ)} for the force Re/Im of A·e^{j(Ωt+φ)}. Frequencies in
// Hz, finite and ≥ 0. Throws std::invalid_argument on a bad model or frequency, and where a
// frequency is exactly the resonance of an undamped (ζ = 0) mode, where H is infinite.
std::vector<std::complex<double>> frequency_response(const ModalModel& model,
                                                     std::span<const double> frequencies);

// The same over default_frequency_grid().
std::vector<std::complex<double>> frequency_response(const ModalModel& model);

}  // namespace nibrig::model::modal
