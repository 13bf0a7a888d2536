// log Φ(x) and the ratio φ(x)/Φ(x) of the standard normal, accurate far into the lower tail where
// Φ underflows: the likelihood of a confidently wrong judgment must stay finite and have a
// gradient.
#pragma once

namespace nibrig::model::space {

// log of the standard normal CDF; finite for every finite x.
double log_normal_cdf(double x);

// φ(x)/Φ(x) (the inverse Mills ratio of −x), the derivative of log Φ; ≈ −x for x → −∞.
double normal_pdf_over_cdf(double x);

// log Φ(x), log Φ(−x) and the two ratios φ/Φ at x and −x together: one erfc where the four
// separately took four (Φ of the smaller side, and 1 − it for the larger, loses nothing), the tail
// forms beyond. The probit likelihood needs all four for every triplet at every evaluation.
struct NormalSides {
  double log_cdf = 0.0, log_cdf_negative = 0.0;
  double pdf_over_cdf = 0.0, pdf_over_cdf_negative = 0.0;
};
NormalSides normal_sides(double x);

}  // namespace nibrig::model::space
