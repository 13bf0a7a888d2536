// Voices for the real-time tests: real catalog spectra (the bundled catalog, derived from the
// paper's recordings) through a small modal model whose response has a closed form.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "model/io/velocity_spectrum.hpp"
#include "model/modal/modal_model.hpp"
#include "rt/voice.hpp"

namespace nibrig::rt::testing {

// The engine's internal rate at a 48 kHz output (the rate a voice steps at).
inline constexpr double kInternalRate = 8000.0;

// The measured acceleration spectrum of `tool` on `surface` from assets/default_catalog.json.
model::io::VelocitySpectrum catalog_spectrum(const std::string& tool, const std::string& surface);

// Three modes like a printed stylus's first ones (a heavily damped bending pair at 92 Hz becomes
// one mode here, a lightly damped one at 250 Hz to give the spectrum a sharp feature, and a stiff
// one at 1.46 kHz).
model::modal::ModalModel small_stylus();

// A voice at internal_rate that reproduces the catalog's acceleration spectrum of tool/surface
// through small_stylus() (rt/voice_builder.hpp).
std::unique_ptr<Voice> catalog_voice(const std::string& tool, const std::string& surface,
                                     double internal_rate, std::uint64_t seed);

}  // namespace nibrig::rt::testing
