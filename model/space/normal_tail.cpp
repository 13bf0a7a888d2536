#include "model/space/normal_tail.hpp"

#include <cmath>

namespace nibrig::model::space {
namespace {

// Mills' ratio Φ(−t)/φ(t) for t ≥ 30 by its continued fraction 1/(t + 1/(t + 2/(t + 3/(t + ...)))),
// evaluated bottom-up; 60 terms give full double precision from t = 5 on, far more than needed.
double mills_ratio(double t) {
  double tail = t;
  for (int k = 60; k >= 1; --k) tail = t + k / tail;
  return 1.0 / tail;
}

}  // namespace

double log_normal_cdf(double x) {
  if (x >= kNormalTail) return std::log(0.5 * std::erfc(-x / kSqrt2));
  const double t = -x;  // Φ(x) = φ(t) · R(t)
  return -0.5 * t * t - kLogSqrt2Pi + std::log(mills_ratio(t));
}

double normal_pdf_over_cdf(double x) {
  if (x >= kNormalTail) {
    const double pdf = std::exp(-0.5 * x * x - kLogSqrt2Pi);
    return pdf / (0.5 * std::erfc(-x / kSqrt2));
  }
  return 1.0 / mills_ratio(-x);
}

NormalSides normal_sides_far(double x, bool log_cdf_wanted, bool log_cdf_negative_wanted) {
  NormalSides s{0.0, 0.0, log_normal_cdf(x), log_normal_cdf(-x), normal_pdf_over_cdf(x),
                normal_pdf_over_cdf(-x)};
  s.cdf = std::exp(s.log_cdf);
  s.cdf_negative = std::exp(s.log_cdf_negative);
  if (!log_cdf_wanted) s.log_cdf = 0.0;
  if (!log_cdf_negative_wanted) s.log_cdf_negative = 0.0;
  return s;
}

}  // namespace nibrig::model::space
