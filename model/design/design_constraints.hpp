// What a printed design must satisfy, beyond lying in the fitted range (the paper's future work,
// Sec. 7): a tip diameter range, the materials a printer may load, and a limit on a proxy the user
// gives per material — a price, a wear rate — summed over the tip's mix by its fractions. Every
// constraint is linear in a design's fractions and tip, so along the line between two designs the
// designs that satisfy them all form one segment, and over a two-material range one rectangle.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "model/design/design_point.hpp"

namespace nibrig::model::design {

struct DesignConstraints {
  std::optional<double> min_tip_m, max_tip_m;
  std::vector<std::string> materials;  // those allowed; empty: every material
  std::map<std::string, double> cost;  // per material, the user's proxy
  std::optional<double> max_cost;      // of a design's mix; needs a cost for each of its materials
  bool any() const {
    return min_tip_m || max_tip_m || !materials.empty() || max_cost;
  }
};

// The ranges every face holds constraints to (the command line's options check the same numbers):
// a tip of 0.01-100 mm, as a design point's; a cost proxy per material and its limit >= 0 and at
// most kLargestDesignCost, so that NaN or 1e308 is refused before a search runs for nothing.
inline constexpr double kSmallestConstraintTipMm = 0.01, kLargestConstraintTipMm = 100.0;
inline constexpr double kLargestDesignCost = 1e15;

// What a face calls each constraint, for the messages: a Python call's arguments by default.
struct ConstraintNames {
  std::string min_tip = "min_tip_mm", max_tip = "max_tip_mm", cost = "cost", max_cost = "max_cost";
};

// Throws std::invalid_argument "<name>: <value>: expected ..." for a tip, cost or limit outside the
// ranges above or not finite, a smallest tip above the largest, a limit without costs, and an
// allowed material named twice or empty. Every search calls it first.
void check_constraints(const DesignConstraints& constraints, const ConstraintNames& names = {});

// "tips 1.5 to 3 mm, materials vero, DM85, cost at most 2 (vero 1, DM85 3)": those set.
std::string describe(const DesignConstraints& constraints);

// Σ fraction · cost over the point's mix. Throws std::invalid_argument naming a material of the mix
// that has no cost.
double design_cost(const DesignPoint& point, const std::map<std::string, double>& cost);

// Empty when the point satisfies every constraint; else the first it breaks, in words ("the tip
// 4 mm is above the largest allowed, 3 mm").
std::string broken_constraint(const DesignPoint& point, const DesignConstraints& constraints);

// The part [lo, hi] of λ in [0, 1] (interpolate(a, b, λ)) whose designs satisfy every constraint;
// lo == hi when one design does. Throws std::invalid_argument when none does, naming the
// constraint that leaves nothing of the line (or saying that they do together, and naming allowed
// materials the line does not hold), and for a cost
// limit without a cost for a material on the line.
std::pair<double, double> feasible_segment(const DesignPoint& a, const DesignPoint& b,
                                           const DesignConstraints& constraints);

}  // namespace nibrig::model::design
