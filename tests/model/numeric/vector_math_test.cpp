#include "model/numeric/vector_math.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

namespace nibrig::model::numeric {
namespace {

// The array functions against the scalar std:: ones, element by element, at lengths that are and
// are not whole vectors (the tail goes element by element). glibc documents libmvec's functions to
// within 4 ulp; 8 ulp of the scalar value leaves room for the scalar's own error.
void expect_close(void (*all)(const double*, double*, std::size_t), double (*one)(double),
                  const std::vector<double>& x, const char* name) {
  for (std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{3}, std::size_t{4},
                        std::size_t{7}, x.size()}) {
    std::vector<double> y(n + 1, -7.0);  // one past the end: must stay untouched
    all(x.data(), y.data(), n);
    for (std::size_t i = 0; i < n; ++i) {
      const double want = one(x[i]);
      const double ulp = std::abs(std::nextafter(want, std::numeric_limits<double>::infinity()) - want);
      EXPECT_LE(std::abs(y[i] - want), 8.0 * ulp)
          << name << "(" << x[i] << ") = " << y[i] << ", want " << want << " (n = " << n << ")";
    }
    EXPECT_EQ(y[n], -7.0) << name << " wrote past " << n << " elements";
  }
}

std::vector<double> evenly(double from, double to, std::size_t count) {
  std::vector<double> x(count);
  for (std::size_t i = 0; i < count; ++i)
    x[i] = from + (to - from) * static_cast<double>(i) / static_cast<double>(count - 1);
  return x;
}

TEST(VectorMath, ErfcExpAndLogAgreeWithTheScalarFunctions) {
  // erfc where the likelihood takes it (|z|/√2 up to 30/√2, Φ down to 1e-198) and beyond, to 26
  // (erfc ≈ 6e-296, still a normal number).
  expect_close(erfc_all, [](double v) { return std::erfc(v); }, evenly(-3.0, 26.0, 1001), "erfc");
  expect_close(exp_all, [](double v) { return std::exp(v); }, evenly(-700.0, 700.0, 1001), "exp");
  std::vector<double> positive = evenly(-300.0, 300.0, 1001);
  for (double& v : positive) v = std::pow(10.0, v);
  expect_close(log_all, [](double v) { return std::log(v); }, positive, "log");
  expect_close(log_all, [](double v) { return std::log(v); }, evenly(0.5, 2.0, 1001), "log near 1");
}

TEST(VectorMath, SinAndCosAgreeWithTheScalarFunctionsOverATurn) {
  // Where the Gaussian draws take them (rt/gaussian_noise.hpp): angles from 0 to 2π, and a few
  // turns beyond for the reduction.
  expect_close(
      sin_all, [](double v) { return std::sin(v); }, evenly(0.0, 2.0 * M_PI, 1001), "sin");
  expect_close(
      cos_all, [](double v) { return std::cos(v); }, evenly(0.0, 2.0 * M_PI, 1001), "cos");
  expect_close(
      sin_all, [](double v) { return std::sin(v); }, evenly(-40.0, 40.0, 1001), "sin, turns");
  expect_close(
      cos_all, [](double v) { return std::cos(v); }, evenly(-40.0, 40.0, 1001), "cos, turns");
}

TEST(VectorMath, TheEdgesAreTheScalarFunctionsEdges) {
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<double> x = {0.0, -800.0, 800.0, inf};
  std::vector<double> y(4);
  log_all(x.data(), y.data(), 1);
  EXPECT_EQ(y[0], -inf);  // log 0: a likelihood of 0 is −∞, as std::log says
  exp_all(x.data() + 1, y.data(), 2);
  EXPECT_EQ(y[0], 0.0);
  EXPECT_EQ(y[1], inf);
  erfc_all(x.data(), y.data(), 4);
  EXPECT_EQ(y[0], 1.0);
  EXPECT_EQ(y[1], 2.0);
  EXPECT_EQ(y[2], 0.0);
  EXPECT_EQ(y[3], 0.0);
}

TEST(VectorMath, ThisMachineUsesLibmvecWhereGlibcHasIt) {
  const char* kind = vector_math_kind();
#if defined(__x86_64__) && defined(__GLIBC__)
  // x86-64 always has SSE2; the vector functions are the point of the module.
  EXPECT_NE(std::strcmp(kind, "scalar"), 0) << kind;
#else
  EXPECT_EQ(std::strcmp(kind, "scalar"), 0) << kind;
#endif
}

}  // namespace
}  // namespace nibrig::model::numeric
