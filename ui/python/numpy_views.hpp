// Eigen's storage lent to numpy: an array that reads the C++ memory in place, kept alive by the
// Python object that owns it, and read-only so that a script cannot change a fitted result behind
// the library's back.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Core>

#include "model/io/velocity_spectrum.hpp"

namespace nibrig::ui::python {

// rows × cols, column-major as Eigen stores it.
inline pybind11::array_t<double> matrix_view(const Eigen::MatrixXd& m, const pybind11::handle& owner) {
  pybind11::array_t<double> a({m.rows(), m.cols()},
                              {static_cast<pybind11::ssize_t>(sizeof(double)),
                               static_cast<pybind11::ssize_t>(sizeof(double) * m.rows())},
                              m.data(), owner);
  pybind11::detail::array_proxy(a.ptr())->flags &= ~pybind11::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

// n contiguous values (an Eigen vector's, a std::vector's).
template <typename T>
pybind11::array_t<T> array_view(const T* data, std::size_t n, const pybind11::handle& owner) {
  pybind11::array_t<T> a({n}, {sizeof(T)}, data, owner);
  pybind11::detail::array_proxy(a.ptr())->flags &= ~pybind11::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

inline pybind11::array_t<double> vector_view(const Eigen::VectorXd& v, const pybind11::handle& owner) {
  return array_view(v.data(), static_cast<std::size_t>(v.size()), owner);
}

// A velocity-binned spectrum's amplitudes as speeds × frequencies, m/s². A copy: the library
// keeps each speed's row as a vector of its own.
inline pybind11::array_t<double> spectrum_array(const model::io::VelocitySpectrum& s) {
  pybind11::array_t<double> a({s.speeds_m_s.size(), s.frequencies_hz.size()});
  auto out = a.mutable_unchecked<2>();
  for (std::size_t v = 0; v < s.speeds_m_s.size(); ++v)
    for (std::size_t f = 0; f < s.frequencies_hz.size(); ++f)
      out(static_cast<pybind11::ssize_t>(v), static_cast<pybind11::ssize_t>(f)) = s.amplitude_m_s2[v][f];
  return a;
}

}  // namespace nibrig::ui::python
