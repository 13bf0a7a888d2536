#include "model/design/single_material_substitute.hpp"

#include <algorithm>
#include <random>

namespace nibrig::model::design {

std::vector<Substitute> single_material_substitutes(const DesignPoint& mix, const Evaluate& from_mix,
                                                    const space::Placement& target, int samples,
                                                    std::uint64_t seed) {
  return single_material_substitutes(mix, from_mix, {target}, space::GroupAim::largest, samples, seed);
}

std::vector<Substitute> single_material_substitutes(const DesignPoint& mix, const Evaluate& from_mix,
                                                    const std::vector<space::Placement>& targets,
                                                    space::GroupAim aim, int samples, std::uint64_t seed) {
  std::vector<Substitute> out;
  if (mix.mix.size() < 2) return out;
  for (const auto& share : mix.mix) {
    Substitute s;
    s.point = DesignPoint{{{share.material, 1.0}}, mix.tip_diameter_m};
    const Candidate c = from_mix(s.point);
    s.cost = c.distance;
    s.cost_sd = c.distance_sd;
    if (!targets.empty()) {
      std::mt19937_64 generator(seed);
      const auto d = space::uncertain_group_distance(c.placement, targets, aim, samples, generator).aggregate;
      s.to_target = d.between_means;
      s.to_target_sd = d.sd;
    }
    out.push_back(s);
  }
  std::stable_sort(out.begin(), out.end(), [](const Substitute& a, const Substitute& b) { return a.cost < b.cost; });
  return out;
}

}  // namespace nibrig::model::design
