#include "model/catalog/friction_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace nibrig::model::catalog {
namespace {

double upper_median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

FrictionComparison compare_with_upstream(const std::vector<FrictionAnalysis>& friction) {
  if (friction.empty()) throw std::invalid_argument("no friction analyses to compare");
  std::vector<double> mu, upstream;
  double sum_abs_diff = 0.0;
  for (const auto& f : friction) {
    mu.push_back(f.fit.mu);
    upstream.push_back(f.upstream_mu);
    sum_abs_diff += std::fabs(f.fit.mu - f.upstream_mu);
  }
  FrictionComparison c;
  const auto [mu_min, mu_max] = std::minmax_element(mu.begin(), mu.end());
  const auto [up_min, up_max] = std::minmax_element(upstream.begin(), upstream.end());
  c.fit_min = *mu_min, c.fit_max = *mu_max, c.fit_median = upper_median(mu);
  c.upstream_min = *up_min, c.upstream_max = *up_max, c.upstream_median = upper_median(upstream);
  c.mean_abs_difference = sum_abs_diff / static_cast<double>(mu.size());
  return c;
}

}  // namespace nibrig::model::catalog
