// Independent references for the spectral tests: a direct O(N²) DFT that shares no code with FFTW
// or model/measure, and the window formula written out again.
#pragma once

#include <cmath>
#include <complex>
#include <numbers>
#include <span>
#include <vector>

namespace nibrig::test {

inline std::vector<std::complex<double>> direct_dft(std::span<const double> x) {
  const std::size_t n = x.size();
  std::vector<std::complex<double>> out(n / 2 + 1);
  for (std::size_t k = 0; k < out.size(); ++k) {
    std::complex<double> sum = 0.0;
    for (std::size_t t = 0; t < n; ++t) {
      // Reduce k·t mod n first: keeps the angle small and the twiddles exact to rounding.
      const double angle =
          -2.0 * std::numbers::pi * static_cast<double>((k * t) % n) / static_cast<double>(n);
      sum += x[t] * std::complex<double>(std::cos(angle), std::sin(angle));
    }
    out[k] = sum;
  }
  return out;
}

inline double hann(std::size_t n, std::size_t length) {
  return std::pow(std::sin(std::numbers::pi * static_cast<double>(n) / static_cast<double>(length)),
                  2);
}

}  // namespace nibrig::test
