// A reference matrix exponential in quadruple precision (GCC's __float128, 113-bit significand) for
// the tests: Taylor series of A/2^s with ‖A/2^s‖∞ ≤ 1/2, then s squarings. It shares nothing with
// the closed forms under test (no poles, no branches), and its ~1e-34 rounding leaves a reference
// good to far better than the 1e-13-level tolerances it is used with.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

namespace nibrig::test {

__extension__ typedef __float128 quad;

class QuadMatrix {
 public:
  explicit QuadMatrix(std::size_t n) : n_(n), a_(n * n, quad(0)) {}
  std::size_t size() const { return n_; }
  quad& operator()(std::size_t r, std::size_t c) { return a_[r * n_ + c]; }
  quad operator()(std::size_t r, std::size_t c) const { return a_[r * n_ + c]; }

  QuadMatrix operator*(const QuadMatrix& b) const {
    QuadMatrix p(n_);
    for (std::size_t r = 0; r < n_; ++r)
      for (std::size_t k = 0; k < n_; ++k) {
        const quad x = (*this)(r, k);
        if (x == quad(0)) continue;
        for (std::size_t c = 0; c < n_; ++c) p(r, c) += x * b(k, c);
      }
    return p;
  }

  double max_row_sum() const {
    double m = 0.0;
    for (std::size_t r = 0; r < n_; ++r) {
      double s = 0.0;
      for (std::size_t c = 0; c < n_; ++c) s += std::abs(static_cast<double>((*this)(r, c)));
      m = std::max(m, s);
    }
    return m;
  }

 private:
  std::size_t n_;
  std::vector<quad> a_;
};

inline QuadMatrix quad_exp(QuadMatrix a) {
  const std::size_t n = a.size();
  int squarings = 0;
  for (double norm = a.max_row_sum(); norm > 0.5; norm /= 2.0) ++squarings;
  const quad scale = quad(std::ldexp(1.0, -squarings));
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t c = 0; c < n; ++c) a(r, c) *= scale;
  // ‖A‖ ≤ ½: the k-th term is below 2^−k/k!, under 1e-40 from k = 30 on.
  QuadMatrix sum(n), term(n);
  for (std::size_t i = 0; i < n; ++i) sum(i, i) = term(i, i) = quad(1);
  for (int k = 1; k <= 32; ++k) {
    term = term * a;
    const quad inv_k = quad(1) / quad(k);
    for (std::size_t r = 0; r < n; ++r)
      for (std::size_t c = 0; c < n; ++c) {
        term(r, c) *= inv_k;
        sum(r, c) += term(r, c);
      }
  }
  for (int s = 0; s < squarings; ++s) sum = sum * sum;
  return sum;
}

}  // namespace nibrig::test
