#include "model/forcing/hermite_curve.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

namespace nibrig::model::forcing {

namespace {

void check_knots(std::span<const double> knots) {
  if (knots.size() < 2) throw std::invalid_argument("Hermite curve: needs at least two knots");
  for (std::size_t k = 0; k < knots.size(); ++k) {
    if (!std::isfinite(knots[k]))
      throw std::invalid_argument("Hermite curve: knot " + std::to_string(k) + " is not finite");
    if (k > 0 && !(knots[k] > knots[k - 1]))
      throw std::invalid_argument("Hermite curve: knots must be strictly increasing (knot " +
                                  std::to_string(k) + ")");
  }
}

// The tangent at knot k as weights on the knot values: a central difference over the neighbours
// inside, a one-sided difference at the ends. Both are exact for a straight line, so the curve
// reproduces linear functions.
std::vector<std::pair<std::size_t, double>> tangent_weights(std::span<const double> knots,
                                                            std::size_t k) {
  const std::size_t lo = k == 0 ? 0 : k - 1;
  const std::size_t hi = k + 1 == knots.size() ? k : k + 1;
  const double span = knots[hi] - knots[lo];
  return {{lo, -1.0 / span}, {hi, 1.0 / span}};
}

}  // namespace

std::vector<double> default_knot_frequencies() {
  std::vector<double> knots;
  for (int k = 0; k <= 10; ++k) knots.push_back(50.0 * k);
  return knots;
}

std::vector<std::pair<std::size_t, double>> hermite_weights(std::span<const double> knots,
                                                            double x) {
  check_knots(knots);
  if (!(x >= knots.front() && x <= knots.back()))
    throw std::invalid_argument("Hermite curve: " + std::to_string(x) +
                                " lies outside the knots [" + std::to_string(knots.front()) + ", " +
                                std::to_string(knots.back()) + "]");
  // The interval [knots[i], knots[i+1]] holding x; the last knot belongs to the last interval.
  const auto upper = std::upper_bound(knots.begin(), knots.end(), x);
  std::size_t i = static_cast<std::size_t>(upper - knots.begin());
  i = std::min(i == 0 ? 0 : i - 1, knots.size() - 2);
  const double h = knots[i + 1] - knots[i];
  const double t = (x - knots[i]) / h;
  const double t2 = t * t, t3 = t2 * t;
  const double h00 = 2 * t3 - 3 * t2 + 1, h10 = t3 - 2 * t2 + t;
  const double h01 = -2 * t3 + 3 * t2, h11 = t3 - t2;

  std::map<std::size_t, double> weights;
  weights[i] += h00;
  weights[i + 1] += h01;
  for (const auto& [k, w] : tangent_weights(knots, i)) weights[k] += h * h10 * w;
  for (const auto& [k, w] : tangent_weights(knots, i + 1)) weights[k] += h * h11 * w;
  return {weights.begin(), weights.end()};
}

double hermite_value(std::span<const double> knots, std::span<const double> values, double x) {
  if (values.size() != knots.size())
    throw std::invalid_argument("Hermite curve: " + std::to_string(values.size()) + " values for " +
                                std::to_string(knots.size()) + " knots");
  double sum = 0.0;
  for (const auto& [k, w] : hermite_weights(knots, x)) sum += w * values[k];
  return sum;
}

}  // namespace nibrig::model::forcing
