// For a printer that cannot mix materials: each material of a mixed design printed alone at the
// same tip, placed in the perceptual space, and how far it falls from the mix (what substituting
// it costs, as a distance in the space) and from the target the mix was searched for.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "model/design/design_search.hpp"

namespace nibrig::model::design {

struct Substitute {
  DesignPoint point;                        // one material, the mix's tip
  double cost = 0.0, cost_sd = 0.0;         // distance of its placement from the mix's
  // From the target (or group) the mix was searched for; none for a design exported without one.
  std::optional<double> to_target;
  double to_target_sd = 0.0;
  // The constraint of the search it breaks (broken_constraint), empty when none: a substitute is
  // what the printer can do, which the user's limits need not allow.
  std::string outside_constraints;
};

// `from_mix` predicts a design and measures its distance to the mix's placement
// (distance_to_target(setup, surface, map, mix placement)); each substitute is predicted once and
// its distance to `target` drawn with `samples` draws of a generator seeded with `seed`, as the
// search draws its own. Nearest to the mix first; empty for a design of one material.
std::vector<Substitute> single_material_substitutes(const DesignPoint& mix, const Evaluate& from_mix,
                                                    const space::Placement& target, int samples = 2000,
                                                    std::uint64_t seed = 1);
// The same for a group design: to_target is the largest or mean distance to the targets, as the
// group's search measured its candidates (space::uncertain_group_distance); no targets: a design
// exported for itself, whose substitutes have no to_target.
std::vector<Substitute> single_material_substitutes(const DesignPoint& mix, const Evaluate& from_mix,
                                                    const std::vector<space::Placement>& targets,
                                                    space::GroupAim aim, int samples = 2000,
                                                    std::uint64_t seed = 1);

}  // namespace nibrig::model::design
