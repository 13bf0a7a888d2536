#include "model/design/design_search.hpp"

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "model/space/catalog_descriptors.hpp"

namespace nibrig::model::design {

namespace {

DesignPoint mix_point(const RangeSearchOptions& o, double second_fraction, double tip_m) {
  DesignPoint point;
  if (second_fraction < 1) point.mix.push_back({o.first_material, 1 - second_fraction});
  if (second_fraction > 0) point.mix.push_back({o.second_material, second_fraction});
  point.tip_diameter_m = tip_m;
  return point;
}

std::string fmt_mm(double m) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g mm", m * 1e3);
  return text;
}

// The golden-section refinement shrinks its bracket by the golden ratio per evaluation until it is
// no wider than the tolerance; the widest bracket is two scan steps (the best point inside).
std::size_t line_search_budget(const LineSearchOptions& o) {
  const double golden = (std::sqrt(5.0) - 1) / 2;
  double width = std::min(1.0, 2.0 / (o.scan_points - 1));
  std::size_t refinements = 2;  // the two interior points of the first bracket
  // The search compares widths it computed step by step; the margin keeps this a bound when its
  // rounding lands a hair above the tolerance.
  while (width > o.refine_tolerance * (1 - 1e-9)) {
    width *= golden;
    ++refinements;
  }
  return static_cast<std::size_t>(o.scan_points) + refinements;
}


}  // namespace

std::vector<std::size_t> ranking(const std::vector<Candidate>& evaluated) {
  std::vector<std::size_t> order(evaluated.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return evaluated[a].search_key() < evaluated[b].search_key();
  });
  return order;
}

bool same_design(const DesignPoint& a, const DesignPoint& b) {
  double variation = 0;
  for (const auto& share : a.mix)
    variation += std::abs(share.fraction - b.fraction_of(share.material));
  for (const auto& share : b.mix)
    if (a.fraction_of(share.material) == 0) variation += share.fraction;
  return variation / 2 < kSameDesignFraction &&
         std::abs(a.tip_diameter_m - b.tip_diameter_m) < kSameDesignTip;
}

std::vector<std::size_t> SearchResult::runners_up(std::size_t count) const {
  std::vector<std::size_t> listed{ranked.at(0)}, out;
  for (std::size_t k = 1; k < ranked.size() && out.size() < count; ++k) {
    const DesignPoint& p = evaluated[ranked[k]].point;
    if (std::any_of(listed.begin(), listed.end(),
                    [&](std::size_t i) { return same_design(evaluated[i].point, p); }))
      continue;
    listed.push_back(ranked[k]);
    out.push_back(ranked[k]);
  }
  return out;
}

Eigen::VectorXd predicted_descriptors(const space::DescriptorMap& map, const PredictedTool& tool) {
  io::Catalog one;
  one.tools.push_back(predicted_tool_entry(tool));
  one.pairings.push_back(predicted_pairing(tool, "the catalog's"));
  const space::DescriptorTable row =
      space::descriptors_of_catalog(one, "prediction", map.descriptor_names.size());
  if (row.names != map.descriptor_names)
    throw std::invalid_argument(
        "the space's descriptor map uses descriptors a prediction does "
        "not provide");
  return row.values.row(0).transpose();
}

space::Placement place_predicted(const space::DescriptorMap& map, const PredictedTool& tool) {
  const Eigen::VectorXd descriptors = predicted_descriptors(map, tool);
  if (tool.descriptor_errors.empty()) return space::place_from_descriptors(map, descriptors);
  return space::place_from_descriptors(map, descriptors,
                                       tool.descriptor_errors.block(map.descriptor_names));
}

Evaluate distance_to_target(const PredictionSetup& setup, const std::string& surface,
                            const space::DescriptorMap& map, const space::Placement& target,
                            int samples, std::uint64_t seed) {
  return distance_to_target(
      [setup, surface](const DesignPoint& point) { return predict_tool(setup, point, surface); }, map,
      target, samples, seed);
}

namespace {

// A design predicted as `tool`, as a candidate: its placement and descriptors, no distance yet.
Candidate placed_candidate(const DesignPoint& point, const PredictedTool& tool, const space::DescriptorMap& map) {
  Candidate c;
  c.point = point;
  c.placement = place_predicted(map, tool);
  c.mu = tool.mu;
  c.weighted_mean = tool.vibration.weighted_mean;
  return c;
}

}  // namespace

Evaluate distance_to_target(Predict predict, const space::DescriptorMap& map,
                            const space::Placement& target, int samples, std::uint64_t seed) {
  return [predict = std::move(predict), map, target, samples, seed](const DesignPoint& point) {
    Candidate c = placed_candidate(point, predict(point), map);
    std::mt19937_64 generator(seed);  // the same draws for every candidate: comparable sds
    const space::UncertainDistance d =
        space::uncertain_distance(c.placement, target, samples, generator);
    c.distance = d.between_means;
    c.distance_sd = d.sd;
    c.target_distances = {c.distance};
    c.target_distance_sds = {c.distance_sd};
    return c;
  };
}

Evaluate distance_to_targets(Predict predict, const space::DescriptorMap& map,
                             std::vector<space::Placement> targets, space::GroupAim aim, int samples,
                             std::uint64_t seed) {
  if (targets.empty()) throw std::invalid_argument("a group design needs at least one target");
  return [predict = std::move(predict), map, targets = std::move(targets), aim, samples,
          seed](const DesignPoint& point) {
    Candidate c = placed_candidate(point, predict(point), map);
    std::mt19937_64 generator(seed);  // the same draws for every candidate: comparable sds
    const auto d = space::uncertain_group_distance(c.placement, targets, aim, samples, generator);
    c.distance = d.aggregate.between_means;
    c.distance_sd = d.aggregate.sd;
    for (const auto& each : d.each) {
      c.target_distances.push_back(each.between_means);
      c.target_distance_sds.push_back(each.sd);
    }
    return c;
  };
}

Evaluate distance_to_targets(const PredictionSetup& setup, const std::string& surface,
                             const space::DescriptorMap& map, std::vector<space::Placement> targets,
                             space::GroupAim aim, int samples, std::uint64_t seed) {
  return distance_to_targets(
      [setup, surface](const DesignPoint& point) { return predict_tool(setup, point, surface); }, map,
      std::move(targets), aim, samples, seed);
}

SearchResult line_search(const DesignPoint& a0, const DesignPoint& b0, const Evaluate& evaluate,
                         const LineSearchOptions& options, const SearchProgress& progress) {
  if (options.scan_points < 2)
    throw std::invalid_argument("line search: at least 2 scan points (the two designs)");
  if (!(options.refine_tolerance > 0 && options.refine_tolerance < 1))
    throw std::invalid_argument("line search: the refinement tolerance is a fraction in (0, 1)");
  SearchResult result;
  // The constraints leave one segment of the line: the search runs along that.
  const auto [from, to] = feasible_segment(a0, b0, options.constraints);
  const DesignPoint a = interpolate(a0, b0, from), b = interpolate(a0, b0, to);
  if (to - from < 1e-9) {  // one design satisfies them: nothing to search
    result.evaluated.push_back(evaluate(a));
    if (progress) progress(result.evaluated.back(), 1, 1);
    result.ranked = {0};
    return result;
  }
  const std::size_t budget = line_search_budget(options);
  std::vector<double> lambdas;
  auto at = [&](double lambda) {
    lambdas.push_back(lambda);
    result.evaluated.push_back(evaluate(interpolate(a, b, lambda)));
    if (progress) progress(result.evaluated.back(), result.evaluated.size(), budget);
    return result.evaluated.back().search_key();
  };
  const int n = options.scan_points;
  std::size_t best = 0;
  for (int k = 0; k < n; ++k) {
    at(static_cast<double>(k) / (n - 1));
    if (result.evaluated.back().search_key() < result.evaluated[best].search_key())
      best = result.evaluated.size() - 1;
  }
  // Golden section inside the steps either side of the best scan point.
  const double step = 1.0 / (n - 1);
  double lo = std::max(0.0, lambdas[best] - step), hi = std::min(1.0, lambdas[best] + step);
  const double golden = (std::sqrt(5.0) - 1) / 2;
  double x1 = hi - golden * (hi - lo), x2 = lo + golden * (hi - lo);
  double f1 = at(x1), f2 = at(x2);
  while (hi - lo > options.refine_tolerance) {
    if (f1 < f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - golden * (hi - lo);
      f1 = at(x1);
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + golden * (hi - lo);
      f2 = at(x2);
    }
  }
  result.ranked = ranking(result.evaluated);
  return result;
}

SearchResult range_search(const Evaluate& evaluate, const RangeSearchOptions& o,
                          const SearchProgress& progress) {
  if (o.fraction_points < 2 || o.tip_points < 2)
    throw std::invalid_argument("range search: at least 2 grid points per axis");
  if (o.first_material == o.second_material)
    throw std::invalid_argument("range search: the mix needs two different materials");
  if (!(o.min_tip_m > 0 && o.max_tip_m > o.min_tip_m))
    throw std::invalid_argument("range search: the tip range must be a positive interval");
  const auto& c = o.constraints;
  const double tip_lo = std::max(o.min_tip_m, c.min_tip_m.value_or(0.0));
  const double tip_hi = std::min(o.max_tip_m, c.max_tip_m.value_or(o.max_tip_m));
  if (tip_lo > tip_hi * (1 + 1e-9))
    throw std::invalid_argument("range search: the allowed tips " + fmt_mm(c.min_tip_m.value_or(o.min_tip_m)) + " to " +
                                fmt_mm(c.max_tip_m.value_or(o.max_tip_m)) + " lie outside the fitted tips " +
                                fmt_mm(o.min_tip_m) + " to " + fmt_mm(o.max_tip_m));
  // The mix's constraints hold alike at every tip: the fractions allowed are one segment.
  DesignConstraints mix_only = c;
  mix_only.min_tip_m.reset(), mix_only.max_tip_m.reset();
  const auto [f_lo, f_hi] = feasible_segment(mix_point(o, 0.0, tip_lo), mix_point(o, 1.0, tip_lo), mix_only);
  const int nf = f_hi - f_lo > 1e-9 ? o.fraction_points : 1;
  const int nt = tip_hi - tip_lo > 1e-12 ? o.tip_points : 1;

  SearchResult result;
  // The first grid, then per refinement the 8 neighbours of the best point (the point itself is
  // known); neighbours outside the range or already evaluated are skipped.
  const std::size_t budget = static_cast<std::size_t>(nf) * static_cast<std::size_t>(nt) +
                             (nf * nt > 1 ? 8 * static_cast<std::size_t>(std::max(0, o.refinements)) : 0);
  std::vector<std::pair<double, double>> done;  // (fraction, tip) evaluated
  auto at = [&](double fraction, double tip) {
    for (const auto& [f, t] : done)
      if (std::abs(f - fraction) < 1e-9 && std::abs(t - tip) < 1e-12) return;
    done.emplace_back(fraction, tip);
    result.evaluated.push_back(evaluate(mix_point(o, fraction, tip)));
    if (progress) progress(result.evaluated.back(), result.evaluated.size(), budget);
  };
  double fraction_step = nf > 1 ? (f_hi - f_lo) / (nf - 1) : 0.0;
  double tip_step = nt > 1 ? (tip_hi - tip_lo) / (nt - 1) : 0.0;
  for (int i = 0; i < nf; ++i)
    for (int j = 0; j < nt; ++j) at(f_lo + i * fraction_step, tip_lo + j * tip_step);
  for (int round = 0; round < o.refinements && nf * nt > 1; ++round) {
    const auto best = ranking(result.evaluated).front();
    const auto [f0, t0] = done[best];
    fraction_step /= 2;
    tip_step /= 2;
    for (int di = -1; di <= 1; ++di)
      for (int dj = -1; dj <= 1; ++dj) {
        const double f = f0 + di * fraction_step, t = t0 + dj * tip_step;
        if (f < f_lo - 1e-12 || f > f_hi + 1e-12 || t < tip_lo - 1e-12 || t > tip_hi + 1e-12) continue;
        at(std::clamp(f, f_lo, f_hi), std::clamp(t, tip_lo, tip_hi));
      }
  }
  result.ranked = ranking(result.evaluated);
  return result;
}

}  // namespace nibrig::model::design
