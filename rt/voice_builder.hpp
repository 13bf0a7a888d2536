// From what a tool should feel like to a voice that sounds like it: the acceleration spectrum the
// sensor should see, A(f, v) (measured in the catalog, or predicted by the forcing model), and the
// stylus whose modes shape it. Control-thread work: allocates, may throw.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "model/io/velocity_spectrum.hpp"
#include "model/modal/modal_model.hpp"
#include "model/modal/voice_source.hpp"
#include "rt/voice.hpp"

namespace nibrig::rt {

// The forcing generator is given A·|H_d| / (|H_d|² + (ε·max|H_d|)²), H_d the modal model's
// response as the voice's integrator computes it at internal_rate_hz
// (model/modal/discrete_frequency_response.hpp), so that the voice's output has the spectrum
// A exactly wherever |H_d| is well above ε of its peak, straight-line joins and folding included;
// where the stylus barely responds the force stays bounded (see model/forcing/measured_forcing.hpp
// for the same regularisation against the continuous response). Equal seeds give equal voices.
std::unique_ptr<Voice> build_voice(std::string name, const model::modal::ModalModel& modal,
                                   const model::io::VelocitySpectrum& acceleration,
                                   double internal_rate_hz, std::uint64_t seed,
                                   double regularisation = 1e-3);

// The voice of `source`, named as it is.
inline std::unique_ptr<Voice> build_voice(const model::modal::VoiceSource& source,
                                          double internal_rate_hz, std::uint64_t seed) {
  return build_voice(source.name, source.modal, source.spectrum, internal_rate_hz, seed);
}

}  // namespace nibrig::rt
