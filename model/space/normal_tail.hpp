// log Φ(x) and the ratio φ(x)/Φ(x) of the standard normal, accurate far into the lower tail where
// Φ underflows: the likelihood of a confidently wrong judgment must stay finite and have a
// gradient.
#pragma once

namespace nibrig::model::space {

// log of the standard normal CDF; finite for every finite x.
double log_normal_cdf(double x);

// φ(x)/Φ(x) (the inverse Mills ratio of −x), the derivative of log Φ; ≈ −x for x → −∞.
double normal_pdf_over_cdf(double x);

}  // namespace nibrig::model::space
