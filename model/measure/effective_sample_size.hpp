// How many independent samples an autocorrelated series is worth: the basis of honest confidence
// intervals for means of force (or any) records sampled much faster than they decorrelate.
#pragma once

#include <cstddef>
#include <span>

namespace nibrig::model::measure {

struct AutocorrelationSummary {
  double variance = 0.0;                 // of the series about its mean (divisor n)
  double integrated_time_samples = 1.0;  // τ = 1 + 2 Σ_{k=1..M} ρ_k, at least 1
  std::size_t window = 0;                // M, the summation window
  double effective_samples = 0.0;        // n / τ
};

// τ by Sokal's automatic window: the smallest M with M >= 5 τ(M) (the standard choice for Monte
// Carlo series; bias O(e^{-5}) for exponential decay). ρ_k comes from an FFT autocorrelation of the
// mean-removed series. For AR(1) with coefficient φ the exact value is (1 + φ)/(1 - φ).
// n >= 2 and finite values, else std::invalid_argument.
AutocorrelationSummary summarize_autocorrelation(std::span<const double> series);

// Standard error of the series mean: sqrt(variance · τ / n).
double standard_error_of_mean(const AutocorrelationSummary& summary, std::size_t n);

}  // namespace nibrig::model::measure
