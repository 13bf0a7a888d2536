#include "model/design/tip_bracket.hpp"

#include <cmath>
#include <stdexcept>

#include "model/forcing/forcing_model.hpp"

namespace nibrig::model::design {

std::vector<double> fitted_tips(const forcing::ForcingModel& model) {
  std::vector<double> tips;
  for (const auto& [d, curve] : model.tip_log_gain) tips.push_back(d);  // std::map: ascending
  return tips;
}

TipBracket bracket_tip(const std::vector<double>& diameters, double d, const std::string& what) {
  if (diameters.empty()) throw std::invalid_argument(what + ": no tip diameters to interpolate");
  if ((d < diameters.front() && !forcing::same_tip(d, diameters.front())) ||
      (d > diameters.back() && !forcing::same_tip(d, diameters.back()))) {
    const bool below = d < diameters.front();
    throw std::invalid_argument(
        what + ": the tip of " + forcing::tip_label(d) + " is " +
        forcing::tip_label(below ? diameters.front() - d : d - diameters.back()) +
        (below ? " below the smallest" : " above the largest") + " diameter there is (" +
        forcing::tip_label(diameters.front()) + " to " + forcing::tip_label(diameters.back()) +
        "); nothing is extrapolated");
  }
  TipBracket b;
  while (b.upper + 1 < diameters.size() && diameters[b.upper] < d &&
         !forcing::same_tip(diameters[b.upper], d))
    ++b.upper;
  b.lower = b.upper == 0 ? 0 : b.upper - 1;
  if (forcing::same_tip(diameters[b.upper], d) || b.lower == b.upper) {
    b.lower = b.upper;
    return b;
  }
  b.weight = (d - diameters[b.lower]) / (diameters[b.upper] - diameters[b.lower]);
  return b;
}

}  // namespace nibrig::model::design
