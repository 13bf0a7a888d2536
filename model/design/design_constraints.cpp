#include "model/design/design_constraints.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

namespace nibrig::model::design {

namespace {

// Fractions and costs within this of a limit satisfy it: the interpolation's rounding.
constexpr double kSlack = 1e-9;

std::string mm(double m) {
  std::ostringstream s;
  s << m * 1e3 << " mm";
  return s.str();
}

bool allowed(const DesignConstraints& c, const std::string& material) {
  return c.materials.empty() || std::find(c.materials.begin(), c.materials.end(), material) != c.materials.end();
}

// λ in [0, 1] with g0 + λ·(g1 − g0) ≤ 0: an interval, empty as lo > hi. An end within `slack` of
// the limit satisfies it; the cut itself is the exact root, so that a design on the limit is
// searched, not one a rounding away from it.
std::pair<double, double> where_at_most(double g0, double g1, double slack) {
  if (g0 <= slack && g1 <= slack) return {0.0, 1.0};
  if (g0 > slack && g1 > slack) return {1.0, 0.0};
  const double root = std::clamp(-g0 / (g1 - g0), 0.0, 1.0);
  return g1 > g0 ? std::pair{0.0, root} : std::pair{root, 1.0};
}

std::string cost_number(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

void check_constraint_value(double value, double low, double high, const std::string& name,
                            const std::string& expected) {
  if (std::isfinite(value) && value >= low && value <= high) return;
  throw std::invalid_argument(name + ": " + cost_number(value) + ": expected " + expected + ", " +
                              cost_number(low) + " to " + cost_number(high));
}

}  // namespace

void check_constraints(const DesignConstraints& c, const ConstraintNames& names) {
  const std::string tip = "a tip diameter in mm";
  if (c.min_tip_m)
    check_constraint_value(*c.min_tip_m * 1e3, kSmallestConstraintTipMm, kLargestConstraintTipMm, names.min_tip, tip);
  if (c.max_tip_m)
    check_constraint_value(*c.max_tip_m * 1e3, kSmallestConstraintTipMm, kLargestConstraintTipMm, names.max_tip, tip);
  if (c.min_tip_m && c.max_tip_m && *c.min_tip_m > *c.max_tip_m)
    throw std::invalid_argument(names.min_tip + ": " + mm(*c.min_tip_m) + " is above " + names.max_tip + ", " +
                                mm(*c.max_tip_m) + ": expected the smallest tip at most the largest");
  std::set<std::string> seen;
  for (const auto& m : c.materials)
    if (m.empty() || !seen.insert(m).second)
      throw std::invalid_argument("allowed materials: '" + m + "' is " + (m.empty() ? "empty" : "named twice"));
  for (const auto& [material, cost] : c.cost) {
    if (material.empty()) throw std::invalid_argument(names.cost + ": a cost without a material");
    check_constraint_value(cost, 0.0, kLargestDesignCost, names.cost + " of " + material, "a cost proxy");
  }
  if (c.max_cost) {
    check_constraint_value(*c.max_cost, 0.0, kLargestDesignCost, names.max_cost, "a cost of a design's mix");
    if (c.cost.empty())
      throw std::invalid_argument(names.max_cost + " limits the cost " + names.cost + " gives each material: give " +
                                  names.cost + " too");
  }
}

std::string describe(const DesignConstraints& c) {
  std::vector<std::string> parts;
  if (c.min_tip_m && c.max_tip_m) parts.push_back("tips " + mm(*c.min_tip_m) + " to " + mm(*c.max_tip_m));
  else if (c.min_tip_m) parts.push_back("tips of at least " + mm(*c.min_tip_m));
  else if (c.max_tip_m) parts.push_back("tips of at most " + mm(*c.max_tip_m));
  if (!c.materials.empty()) {
    std::string m = "materials";
    for (std::size_t i = 0; i < c.materials.size(); ++i) m += (i ? ", " : " ") + c.materials[i];
    parts.push_back(m);
  }
  if (c.max_cost) {
    std::ostringstream s;
    s << "cost at most " << *c.max_cost << " (";
    bool first = true;
    for (const auto& [material, cost] : c.cost) s << (first ? "" : ", ") << material << " " << cost, first = false;
    s << ")";
    parts.push_back(s.str());
  }
  std::string out;
  for (const auto& p : parts) out += (out.empty() ? "" : ", ") + p;
  return out;
}

double design_cost(const DesignPoint& point, const std::map<std::string, double>& cost) {
  double sum = 0.0;
  for (const auto& share : point.mix) {
    const auto it = cost.find(share.material);
    if (it == cost.end())
      throw std::invalid_argument("no cost given for " + share.material + ", a material of " + label(point));
    sum += share.fraction * it->second;
  }
  return sum;
}

std::string broken_constraint(const DesignPoint& point, const DesignConstraints& c) {
  const double tip = point.tip_diameter_m;
  if (c.min_tip_m && tip < *c.min_tip_m * (1 - kSlack))
    return "the tip " + mm(tip) + " is below the smallest allowed, " + mm(*c.min_tip_m);
  if (c.max_tip_m && tip > *c.max_tip_m * (1 + kSlack))
    return "the tip " + mm(tip) + " is above the largest allowed, " + mm(*c.max_tip_m);
  for (const auto& share : point.mix)
    if (share.fraction > kSlack && !allowed(c, share.material)) return share.material + " is not an allowed material";
  if (c.max_cost) {
    const double cost = design_cost(point, c.cost);
    if (cost > *c.max_cost + kSlack * std::max(1.0, std::abs(*c.max_cost))) {
      std::ostringstream s;
      s << "its cost " << cost << " is above the limit " << *c.max_cost;
      return s.str();
    }
  }
  return {};
}

std::pair<double, double> feasible_segment(const DesignPoint& a, const DesignPoint& b,
                                           const DesignConstraints& c) {
  check_constraints(c);
  const std::string line = label(a) + " -> " + label(b);
  std::pair<double, double> all{0.0, 1.0};
  // Each constraint's own interval first, so that one which leaves nothing is named.
  const auto take = [&](std::pair<double, double> own, const std::string& what) {
    if (own.first > own.second) throw std::invalid_argument("no design on the line " + line + " has " + what);
    all = {std::max(all.first, own.first), std::min(all.second, own.second)};
  };
  const double ta = a.tip_diameter_m, tb = b.tip_diameter_m;
  if (c.min_tip_m)
    take(where_at_most(*c.min_tip_m - ta, *c.min_tip_m - tb, kSlack * *c.min_tip_m), "a tip of at least " + mm(*c.min_tip_m));
  if (c.max_tip_m)
    take(where_at_most(ta - *c.max_tip_m, tb - *c.max_tip_m, kSlack * *c.max_tip_m), "a tip of at most " + mm(*c.max_tip_m));
  std::set<std::string> materials;
  for (const auto* p : {&a, &b})
    for (const auto& share : p->mix) materials.insert(share.material);
  // Allowed materials the line does not hold: named when nothing is left, as "--allow steel" on a
  // line of vero and DM85 is the likely slip.
  std::string absent;
  for (const auto& m : c.materials)
    if (!materials.count(m)) absent += (absent.empty() ? "" : ", ") + m;
  const std::string absent_note =
      absent.empty() ? "" : " (allowed " + absent + ": not a material of the line)";
  for (const auto& m : materials)
    if (!allowed(c, m))
      take(where_at_most(a.fraction_of(m), b.fraction_of(m), kSlack), "no " + m + " (not allowed)" + absent_note);
  if (c.max_cost) {
    std::ostringstream what;
    what << "a cost of at most " << *c.max_cost;
    take(where_at_most(design_cost(a, c.cost) - *c.max_cost, design_cost(b, c.cost) - *c.max_cost,
                       kSlack * std::max(1.0, std::abs(*c.max_cost))),
         what.str());
  }
  if (all.first > all.second)
    throw std::invalid_argument("no design on the line " + line + " satisfies the constraints together" +
                                absent_note);
  return all;
}

}  // namespace nibrig::model::design
