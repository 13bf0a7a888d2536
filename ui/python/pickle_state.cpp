#include "ui/python/pickle_state.hpp"

#include <pybind11/stl.h>

#include <cstring>
#include <map>
#include <stdexcept>
#include <utility>

namespace nibrig::ui::python {

namespace py = pybind11;

void require_state(const py::tuple& state, std::size_t size, const std::string& type) {
  if (state.size() != size) throw std::invalid_argument(type + ": not a pickled " + type);
}

std::string path_state(const std::filesystem::path& path) { return path.string(); }

std::filesystem::path path_of(const py::handle& state) { return state.cast<std::string>(); }

py::bytes float_bytes(const std::vector<float>& samples) {
  return {reinterpret_cast<const char*>(samples.data()), samples.size() * sizeof(float)};
}

std::vector<float> floats_of(const py::handle& bytes, const std::string& type) {
  const auto text = bytes.cast<std::string>();
  if (text.size() % sizeof(float) != 0)
    throw std::invalid_argument(type + ": not a pickled " + type);
  std::vector<float> out(text.size() / sizeof(float));
  std::memcpy(out.data(), text.data(), text.size());
  return out;
}

py::tuple design_point_state(const model::design::DesignPoint& point) {
  std::vector<std::pair<std::string, double>> mix;
  for (const auto& share : point.mix) mix.emplace_back(share.material, share.fraction);
  return py::make_tuple(mix, point.tip_diameter_m);
}

model::design::DesignPoint design_point_of(const py::handle& state, const std::string& type) {
  const auto t = state.cast<py::tuple>();
  require_state(t, 2, type);
  model::design::DesignPoint point;
  for (const auto& [material, fraction] : t[0].cast<std::vector<std::pair<std::string, double>>>())
    point.mix.push_back({material, fraction});
  point.tip_diameter_m = t[1].cast<double>();
  return point;
}

py::tuple modal_state(const model::modal::ModalModel& modal) {
  return py::make_tuple(modal.omega, modal.zeta, modal.input, modal.output);
}

model::modal::ModalModel modal_of(const py::handle& state, const std::string& type) {
  const auto t = state.cast<py::tuple>();
  require_state(t, 4, type);
  return {t[0].cast<std::vector<double>>(), t[1].cast<std::vector<double>>(),
          t[2].cast<std::vector<double>>(), t[3].cast<std::vector<double>>()};
}

py::tuple spectrum_state(const model::io::VelocitySpectrum& spectrum) {
  return py::make_tuple(spectrum.frequencies_hz, spectrum.speeds_m_s, spectrum.amplitude_m_s2);
}

model::io::VelocitySpectrum spectrum_of(const py::handle& state, const std::string& type) {
  const auto t = state.cast<py::tuple>();
  require_state(t, 3, type);
  return {t[0].cast<std::vector<double>>(), t[1].cast<std::vector<double>>(),
          t[2].cast<std::vector<std::vector<double>>>()};
}

py::tuple descriptors_state(const model::measure::VibrationDescriptors& descriptors) {
  return py::make_tuple(descriptors.weighted_mean, descriptors.weighted_power,
                        descriptors.band_energies);
}

model::measure::VibrationDescriptors descriptors_of(const py::handle& state,
                                                    const std::string& type) {
  const auto t = state.cast<py::tuple>();
  require_state(t, 3, type);
  return {t[0].cast<double>(), t[1].cast<double>(),
          t[2].cast<std::map<int, std::vector<double>>>()};
}

}  // namespace nibrig::ui::python
