// Argument checks shared by every entry point of the integrator: a ModalModel, a sample rate, a
// count. They throw std::invalid_argument naming the caller, the field, the index and the value, so
// that a bad model is reported where it enters and never reaches the numerics (or the audio
// thread).
#pragma once

#include <cstddef>
#include <string>

#include "model/modal/modal_model.hpp"

namespace nibrig::model::modal {

// Equal sizes, at least one mode, ω finite and > 0, ζ finite and ≥ 0, b and c finite.
void check_modal_model(const ModalModel& model, const std::string& caller);

// Finite and > 0, in Hz.
void check_sample_rate(double sample_rate, const std::string& caller);

// A value that must be finite (amplitude, phase, frequency, force); `what` names it in the message.
void check_finite(double value, const std::string& what, const std::string& caller);

// Two sequences that must have the same length.
void check_same_size(std::size_t size, std::size_t expected, const std::string& what,
                     const std::string& caller);

// A number as the messages print it: shortest round-trip form, "nan" and "inf" as such.
std::string format_number(double value);

}  // namespace nibrig::model::modal
