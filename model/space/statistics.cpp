#include "model/space/statistics.hpp"

#include <algorithm>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace nibrig::model::space {
namespace {

void check_pairs(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.size() != y.size())
    throw std::invalid_argument("correlation: " + std::to_string(x.size()) + " values against " +
                                std::to_string(y.size()));
  if (x.size() < 3)
    throw std::invalid_argument("correlation needs at least 3 pairs, got " +
                                std::to_string(x.size()));
}

double two_sided_t_p_value(double r, std::size_t n) {
  const double dof = static_cast<double>(n) - 2.0;
  if (std::abs(r) >= 1.0) return 0.0;
  const double t = r * std::sqrt(dof / (1.0 - r * r));
  const boost::math::students_t distribution(dof);
  return 2.0 * boost::math::cdf(boost::math::complement(distribution, std::abs(t)));
}

std::vector<double> ranks(const std::vector<double>& v) {
  std::vector<std::size_t> order(v.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return v[a] < v[b]; });
  std::vector<double> rank(v.size());
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j + 1 < order.size() && v[order[j + 1]] == v[order[i]]) ++j;
    const double mean_rank = 0.5 * static_cast<double>(i + j) + 1.0;
    for (std::size_t k = i; k <= j; ++k) rank[order[k]] = mean_rank;
    i = j + 1;
  }
  return rank;
}

}  // namespace

Correlation pearson(const std::vector<double>& x, const std::vector<double>& y) {
  check_pairs(x, y);
  const double n = static_cast<double>(x.size());
  const double mx = std::accumulate(x.begin(), x.end(), 0.0) / n;
  const double my = std::accumulate(y.begin(), y.end(), 0.0) / n;
  double sxy = 0.0, sxx = 0.0, syy = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
    syy += (y[i] - my) * (y[i] - my);
  }
  if (sxx == 0.0 || syy == 0.0)
    throw std::invalid_argument("correlation of a constant series is undefined");
  Correlation c;
  c.n = x.size();
  c.r = std::clamp(sxy / std::sqrt(sxx * syy), -1.0, 1.0);
  c.p_value = two_sided_t_p_value(c.r, c.n);
  return c;
}

Correlation spearman(const std::vector<double>& x, const std::vector<double>& y) {
  check_pairs(x, y);
  return pearson(ranks(x), ranks(y));
}

AgreementTest agreement_test(double agreements, double trials) {
  if (!(trials > 0) || agreements < 0 || agreements > trials)
    throw std::invalid_argument("agreement test: " + std::to_string(agreements) + " of " +
                                std::to_string(trials));
  AgreementTest t;
  t.agreements = agreements;
  t.trials = trials;
  t.fraction = agreements / trials;
  t.z = (agreements - 0.5 * trials) / std::sqrt(0.25 * trials);
  t.p_value = boost::math::cdf(boost::math::complement(boost::math::normal(), t.z));
  return t;
}

}  // namespace nibrig::model::space
