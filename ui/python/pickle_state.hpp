// What the classes that pickle share: their state's size checked, float samples as bytes (a minute
// of audio at 48 kHz is 11 MB as bytes, several times that as a list of Python floats), and the
// states of the records several of them hold.
#pragma once

#include <pybind11/pybind11.h>

#include <filesystem>
#include <string>
#include <vector>

#include "model/design/design_point.hpp"
#include "model/io/velocity_spectrum.hpp"
#include "model/measure/descriptors.hpp"
#include "model/modal/modal_model.hpp"

namespace nibrig::ui::python {

// Throws ValueError "<type>: not a pickled <type>" unless the state has `size` items.
void require_state(const pybind11::tuple& state, std::size_t size, const std::string& type);

// A path as text and back: an empty path (none given) would come back from Python's Path as ".".
std::string path_state(const std::filesystem::path& path);
std::filesystem::path path_of(const pybind11::handle& state);

pybind11::bytes float_bytes(const std::vector<float>& samples);
std::vector<float> floats_of(const pybind11::handle& bytes, const std::string& type);

// Each record as a tuple of its numbers and back, bit for bit; `type` names the class whose state
// holds it in a refusal.
pybind11::tuple design_point_state(const model::design::DesignPoint& point);
model::design::DesignPoint design_point_of(const pybind11::handle& state, const std::string& type);
pybind11::tuple modal_state(const model::modal::ModalModel& modal);
model::modal::ModalModel modal_of(const pybind11::handle& state, const std::string& type);
pybind11::tuple spectrum_state(const model::io::VelocitySpectrum& spectrum);
model::io::VelocitySpectrum spectrum_of(const pybind11::handle& state, const std::string& type);
pybind11::tuple descriptors_state(const model::measure::VibrationDescriptors& descriptors);
model::measure::VibrationDescriptors descriptors_of(const pybind11::handle& state,
                                                    const std::string& type);

}  // namespace nibrig::ui::python
