#include "model/space/normal_tail.hpp"

#include <cmath>

namespace nibrig::model::space {
namespace {

constexpr double kSqrt2 = 1.4142135623730951;
constexpr double kLogSqrt2Pi = 0.91893853320467274;  // log √(2π)
// Below this Φ(x) = erfc(−x/√2)/2 loses relative accuracy to cancellation-free but
// underflow-bound erfc; the continued fraction is used instead.
constexpr double kTail = -5.0;

// Mills' ratio Φ(−t)/φ(t) for t ≥ 5 by its continued fraction 1/(t + 1/(t + 2/(t + 3/(t + ...)))),
// evaluated bottom-up; 60 terms give full double precision from t = 5 on.
double mills_ratio(double t) {
  double tail = t;
  for (int k = 60; k >= 1; --k) tail = t + k / tail;
  return 1.0 / tail;
}

}  // namespace

double log_normal_cdf(double x) {
  if (x >= kTail) return std::log(0.5 * std::erfc(-x / kSqrt2));
  const double t = -x;  // Φ(x) = φ(t) · R(t)
  return -0.5 * t * t - kLogSqrt2Pi + std::log(mills_ratio(t));
}

double normal_pdf_over_cdf(double x) {
  if (x >= kTail) {
    const double pdf = std::exp(-0.5 * x * x - kLogSqrt2Pi);
    return pdf / (0.5 * std::erfc(-x / kSqrt2));
  }
  return 1.0 / mills_ratio(-x);
}

NormalSides normal_sides(double x) {
  const double t = std::abs(x);
  if (-t < kTail)
    return {log_normal_cdf(x), log_normal_cdf(-x), normal_pdf_over_cdf(x), normal_pdf_over_cdf(-x)};
  const double small = 0.5 * std::erfc(t / kSqrt2);  // Φ(−t) ≤ ½
  const double pdf = std::exp(-0.5 * t * t - kLogSqrt2Pi);
  const double log_small = std::log(small), log_large = std::log1p(-small);
  const double ratio_small = pdf / small, ratio_large = pdf / (1.0 - small);
  if (x >= 0) return {log_large, log_small, ratio_large, ratio_small};
  return {log_small, log_large, ratio_small, ratio_large};
}

}  // namespace nibrig::model::space
