// log Φ(x) and the ratio φ(x)/Φ(x) of the standard normal, accurate far into the lower tail where
// Φ underflows: the likelihood of a confidently wrong judgment must stay finite and have a
// gradient.
#pragma once

#include <cmath>

namespace nibrig::model::space {

inline constexpr double kSqrt2 = 1.4142135623730951;
inline constexpr double kLogSqrt2Pi = 0.91893853320467274;  // log √(2π)
// Below this Φ(x) = erfc(−x/√2)/2 nears erfc's underflow (Φ(−37.5) ≈ 1e-307), and the continued
// fraction is used instead. erfc of a large argument keeps its full relative precision until then
// (it is not 1 − erf), so the bound sits far out: nearer the middle, the many confident triplets of
// a fitted space would each go through the slower continued fraction.
inline constexpr double kNormalTail = -30.0;

// log of the standard normal CDF; finite for every finite x.
double log_normal_cdf(double x);

// φ(x)/Φ(x) (the inverse Mills ratio of −x), the derivative of log Φ; ≈ −x for x → −∞.
double normal_pdf_over_cdf(double x);

// Φ(x), Φ(−x), their logs and the two ratios φ/Φ at x and −x together: one erfc where the four
// separately took four (Φ of the smaller side, and 1 − it for the larger, loses nothing), the tail
// forms beyond. The probit likelihood needs the ratios for every triplet at every evaluation, and
// a log only for a side some answer took (half of Lagunas's triplets were unanimous) and only
// without a lapse (which mixes the probabilities themselves): a log not wanted is left at 0.
struct NormalSides {
  double cdf = 0.0, cdf_negative = 0.0;  // 0 where they underflow, far in a tail
  double log_cdf = 0.0, log_cdf_negative = 0.0;
  double pdf_over_cdf = 0.0, pdf_over_cdf_negative = 0.0;
};

// log(1 − small) for the larger side of a probit, given log_large = log(1 − small) as computed
// (std::log or a vector log): a sum of likelihoods needs an absolute error of 1e-16, which log of
// the rounded 1 − small gives (log1p took twice its time); below 1e-8 the series −small − small²/2,
// exact to 1e-24, is used instead.
inline double log_larger_side(double small, double log_large) {
  return small < 1e-8 ? -small * (1.0 + 0.5 * small) : log_large;
}

// Inline: the probit likelihood's innermost call. |x| > −kNormalTail goes to normal_sides_far.
NormalSides normal_sides_far(double x, bool log_cdf_wanted, bool log_cdf_negative_wanted);
inline NormalSides normal_sides(double x, bool log_cdf_wanted = true,
                                bool log_cdf_negative_wanted = true) {
  const double t = std::abs(x);
  if (-t < kNormalTail) return normal_sides_far(x, log_cdf_wanted, log_cdf_negative_wanted);
  const double small = 0.5 * std::erfc(t / kSqrt2), large = 1.0 - small;  // Φ(−t) ≤ ½, Φ(t)
  const double pdf = std::exp(-0.5 * t * t - kLogSqrt2Pi);
  const bool small_is_cdf = x < 0;
  const bool small_log = small_is_cdf ? log_cdf_wanted : log_cdf_negative_wanted;
  const bool large_log = small_is_cdf ? log_cdf_negative_wanted : log_cdf_wanted;
  const double log_small = small_log ? std::log(small) : 0.0;
  const double log_large = large_log ? log_larger_side(small, std::log(large)) : 0.0;
  const double ratio_small = pdf / small, ratio_large = pdf / large;
  if (small_is_cdf) return {small, large, log_small, log_large, ratio_small, ratio_large};
  return {large, small, log_large, log_small, ratio_large, ratio_small};
}

}  // namespace nibrig::model::space
