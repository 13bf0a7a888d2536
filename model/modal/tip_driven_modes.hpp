// The modes a force at the tip drives: those whose tip participation is not (numerically) zero.
// A symmetric bar's in-plane and torsion modes have none along z, so these are its bending modes
// in the thickness direction — the ones the demo holds against beam theory.
#pragma once

#include <cstddef>
#include <vector>

#include "model/modal/modal_model.hpp"

namespace nibrig::model::modal {

// The frequencies (Hz) of the first `count` modes, in the model's order, whose |input| exceeds
// `relative` times the largest |input|.
std::vector<double> tip_driven_frequencies_hz(const ModalModel& modal, std::size_t count,
                                              double relative = 1e-3);

}  // namespace nibrig::model::modal
