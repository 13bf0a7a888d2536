// Eigen's storage lent to numpy: an array that reads the C++ memory in place, kept alive by the
// Python object that owns it, and read-only so that a script cannot change a fitted result behind
// the library's back.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <vector>

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

// cols × rows: each column a row of the array, the transpose lent without a copy (a column-major
// matrix's columns are contiguous, so the view is C-ordered).
inline pybind11::array_t<double> columns_as_rows_view(const Eigen::MatrixXd& m,
                                                      const pybind11::handle& owner) {
  pybind11::array_t<double> a({m.cols(), m.rows()},
                              {static_cast<pybind11::ssize_t>(sizeof(double) * m.rows()),
                               static_cast<pybind11::ssize_t>(sizeof(double))},
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

// A table kept as rows of their own (each a std::vector of the same length) as a 2-D array: a copy.
inline pybind11::array_t<double> rows_array(const std::vector<std::vector<double>>& rows) {
  const std::size_t columns = rows.empty() ? 0 : rows.front().size();
  pybind11::array_t<double> a({rows.size(), columns});
  auto out = a.mutable_unchecked<2>();
  for (std::size_t r = 0; r < rows.size(); ++r)
    for (std::size_t c = 0; c < columns; ++c)
      out(static_cast<pybind11::ssize_t>(r), static_cast<pybind11::ssize_t>(c)) = rows[r][c];
  return a;
}

// A velocity-binned spectrum's amplitudes as speeds × frequencies, m/s² (a copy).
inline pybind11::array_t<double> spectrum_array(const model::io::VelocitySpectrum& s) {
  return rows_array(s.amplitude_m_s2);
}

}  // namespace nibrig::ui::python
