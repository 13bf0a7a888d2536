#include "model/mechanics/beam_theory.hpp"

#include <cmath>
#include <stdexcept>

namespace nibrig::model::mechanics {

std::vector<double> cantilever_roots(int n) {
  if (n < 1) throw std::invalid_argument("cantilever roots: ask for at least one");
  std::vector<double> roots;
  for (int k = 1; k <= n; ++k) {
    // Root k lies within (k − ½)π ± ½π, near (k − ½)π for large k; cos·cosh + 1 changes sign once
    // there. Bisection then Newton-free refinement to the last bit.
    double lo = (k - 1) * M_PI + (k == 1 ? 0.5 : 0.0), hi = k * M_PI;
    auto f = [](double x) { return std::cos(x) * std::cosh(x) + 1.0; };
    if (f(lo) * f(hi) > 0) throw std::logic_error("cantilever roots: bracket lost");
    for (int i = 0; i < 200 && hi - lo > 4 * std::numeric_limits<double>::epsilon() * hi; ++i) {
      const double mid = 0.5 * (lo + hi);
      (f(lo) * f(mid) <= 0 ? hi : lo) = mid;
    }
    roots.push_back(0.5 * (lo + hi));
  }
  return roots;
}

std::vector<double> cantilever_bending_frequencies(double youngs_modulus, double density,
                                                   double free_length, double width,
                                                   double thickness, int n) {
  for (double v : {youngs_modulus, density, free_length, width, thickness})
    if (!(std::isfinite(v) && v > 0))
      throw std::invalid_argument("cantilever frequencies: every parameter must be positive");
  const double inertia = width * thickness * thickness * thickness / 12, area = width * thickness;
  const double scale = std::sqrt(youngs_modulus * inertia / (density * area)) /
                       (2 * M_PI * free_length * free_length);
  std::vector<double> frequencies;
  for (double beta_l : cantilever_roots(n)) frequencies.push_back(beta_l * beta_l * scale);
  return frequencies;
}

}  // namespace nibrig::model::mechanics
