// What the classes that pickle share: their state's size checked, and float samples as bytes (a
// minute of audio at 48 kHz is 11 MB as bytes, several times that as a list of Python floats).
#pragma once

#include <pybind11/pybind11.h>

#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace nibrig::ui::python {

// Throws ValueError "<type>: not a pickled <type>" unless the state has `size` items.
inline void require_state(const pybind11::tuple& state, std::size_t size, const std::string& type) {
  if (state.size() != size) throw std::invalid_argument(type + ": not a pickled " + type);
}

inline pybind11::bytes float_bytes(const std::vector<float>& samples) {
  return {reinterpret_cast<const char*>(samples.data()), samples.size() * sizeof(float)};
}

inline std::vector<float> floats_of(const pybind11::handle& bytes, const std::string& type) {
  const auto text = bytes.cast<std::string>();
  if (text.size() % sizeof(float) != 0)
    throw std::invalid_argument(type + ": not a pickled " + type);
  std::vector<float> out(text.size() / sizeof(float));
  std::memcpy(out.data(), text.data(), text.size());
  return out;
}

}  // namespace nibrig::ui::python
