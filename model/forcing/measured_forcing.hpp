// The forcing behind a measured tool: the spectrum F(f, v) that, passed through a stylus's modal
// response H(f), gives the acceleration spectrum recorded for that tool on that surface. This is
// how a catalog tool becomes a real-time voice before the data-driven forcing model (Sec. 5.2)
// predicts F for tools nobody measured.
#pragma once

#include "model/io/velocity_spectrum.hpp"
#include "model/modal/modal_model.hpp"

namespace nibrig::model::forcing {

// F = A·|H| / (|H|² + (ε·max|H|)²) at every frequency and speed, with max|H| over the spectrum's
// frequencies: A/|H| wherever |H| is well above ε of its peak, and bounded where the stylus barely
// responds (below its first mode |H| falls as f², and dividing by it would ask for huge forces
// that only a measurement's noise floor produced). Speeds and frequencies are those of
// `acceleration`; the amplitudes become N. Throws std::invalid_argument for ε < 0, a bad model
// or a frequency where H is infinite (an undamped resonance).
io::VelocitySpectrum forcing_from_acceleration(const io::VelocitySpectrum& acceleration,
                                               const modal::ModalModel& model,
                                               double regularisation = 1e-3);

}  // namespace nibrig::model::forcing
