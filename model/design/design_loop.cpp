#include "model/design/design_loop.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "model/space/catalog_descriptors.hpp"

namespace nibrig::model::design {

std::string rule_name(NextPrintRule rule) {
  return rule == NextPrintRule::predicted_optimum ? "optimum" : "likeliest";
}

NextPrintRule parse_next_print_rule(const std::string& name) {
  if (name == "optimum") return NextPrintRule::predicted_optimum;
  if (name == "likeliest") return NextPrintRule::likeliest_within_threshold;
  throw std::invalid_argument("'" + name +
                              "' is not a rule for the next print: optimum (the predicted optimum) "
                              "or likeliest (the likeliest to land within the threshold)");
}

double just_noticeable_distance(const space::JudgmentModel& model, std::size_t dims) {
  space::JudgmentModel attentive = model;
  attentive.lapse = 0.0;
  const double log_sigma = space::typical_log_sigma(model);
  // P(the target judged closer to itself than the print) rises from ½ with the print's distance.
  const auto target_chosen = [&](double distance) {
    return space::probability_first(attentive, dims, 0.0, distance, log_sigma);
  };
  double lo = 0.0, hi = 1.0;
  while (target_chosen(hi) < 0.75 && hi < 1e6) hi *= 2;
  if (!(target_chosen(hi) >= 0.75))
    throw std::invalid_argument("the space's judgment model never tells a print from its target");
  for (int k = 0; k < 100 && hi - lo > 1e-12 * hi; ++k) {
    const double mid = 0.5 * (lo + hi);
    (target_chosen(mid) < 0.75 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

Eigen::VectorXd measured_descriptors(const space::DescriptorMap& map, const io::Pairing& pairing) {
  io::Catalog one;
  one.pairings.push_back(pairing);
  const space::DescriptorTable row =
      space::descriptors_of_catalog(one, "the measured print", map.descriptor_names.size());
  if (row.values.rows() != 1)
    throw std::invalid_argument("the measured print " + space::pairing_name(pairing) +
                                " has no friction or no vibration descriptors");
  if (row.names != map.descriptor_names)
    throw std::invalid_argument(
        "the space's descriptor map uses descriptors a measurement does not provide");
  return row.values.row(0).transpose();
}

namespace {

// P(‖x − target‖ ≤ radius) for x ~ N(mean, covariance), over `samples` draws seeded alike for
// every design (common draws: chances compared between designs do not differ by their noise).
double chance_within(const Eigen::VectorXd& mean, const Eigen::MatrixXd& covariance,
                     const Eigen::VectorXd& target, double radius, int samples,
                     std::uint64_t seed) {
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(covariance);
  const Eigen::MatrixXd root =
      eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).cwiseSqrt().asDiagonal();
  std::mt19937_64 generator(seed);
  std::normal_distribution<double> normal;
  Eigen::VectorXd z(mean.size());
  int inside = 0;
  for (int s = 0; s < samples; ++s) {
    for (Eigen::Index k = 0; k < z.size(); ++k) z(k) = normal(generator);
    if ((mean + root * z - target).norm() <= radius) ++inside;
  }
  return static_cast<double>(inside) / samples;
}

}  // namespace

LoopPrediction predict_in_loop(const LoopContext& context, const PrintDiscrepancy& discrepancy,
                               const PredictedTool& tool) {
  const space::DescriptorMap& map = *context.map;
  const DescriptorCorrection correction = discrepancy.at(tool.point);
  LoopPrediction out;
  out.descriptors = predicted_descriptors(map, tool) + correction.mean;
  Candidate& c = out.candidate;
  c.point = tool.point;
  c.placement = space::place_from_descriptors(map, out.descriptors, correction.covariance);
  c.mu = tool.mu;
  c.weighted_mean = tool.vibration.weighted_mean;
  std::mt19937_64 generator(context.seed);
  const space::UncertainDistance d =
      space::uncertain_distance(c.placement, context.target, context.samples, generator);
  c.distance = d.between_means;
  c.distance_sd = d.sd;
  c.target_distances = {c.distance};
  c.target_distance_sds = {c.distance_sd};
  // Where its measurement will lie: the map is the same for the measured print and the prediction,
  // so only the prediction's error and the measurement's noise move it (J·Σ·Jᵀ, the map linear).
  const space::Placement bare = space::place_from_descriptors(map, out.descriptors);
  const space::Placement spread = space::place_from_descriptors(
      map, out.descriptors, correction.covariance + context.measurement_noise);
  out.chance_within =
      chance_within(bare.mean, spread.covariance - bare.covariance, context.target.mean,
                    context.threshold, context.samples, context.seed);
  return out;
}

MeasuredPlacement place_measured(const LoopContext& context, const io::Pairing& pairing) {
  MeasuredPlacement out;
  out.descriptors = measured_descriptors(*context.map, pairing);
  out.placement = space::place_from_descriptors(*context.map, out.descriptors);
  std::mt19937_64 generator(context.seed);
  const space::UncertainDistance d =
      space::uncertain_distance(out.placement, context.target, context.samples, generator);
  out.distance = d.between_means;
  out.distance_sd = d.sd;
  return out;
}

Proposal propose_next_print(const LoopContext& context, const PrintDiscrepancy& discrepancy,
                            const Predict& predict, const RangeSearchOptions& range,
                            NextPrintRule rule, const std::vector<DesignPoint>& candidates,
                            const std::vector<DesignPoint>& printed) {
  Proposal proposal;
  std::vector<LoopPrediction> predictions;
  const Evaluate evaluate = [&](const DesignPoint& point) {
    LoopPrediction p = predict_in_loop(context, discrepancy, predict(point));
    p.candidate.score = rule == NextPrintRule::predicted_optimum
                            ? p.candidate.distance
                            // Ties in chance (all 0 far away, all 1 close by) go to the nearer.
                            : -p.chance_within + 1e-6 * p.candidate.distance;
    predictions.push_back(p);
    return p.candidate;
  };
  if (candidates.empty()) {
    proposal.search = range_search(evaluate, range);
  } else {
    for (const auto& c : candidates) proposal.search.evaluated.push_back(evaluate(c));
    std::vector<std::size_t>& order = proposal.search.ranked;
    for (std::size_t k = 0; k < candidates.size(); ++k) order.push_back(k);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return proposal.search.evaluated[a].search_key() < proposal.search.evaluated[b].search_key();
    });
  }
  for (const auto& p : predictions) proposal.chances.push_back(p.chance_within);
  const auto is_printed = [&](std::size_t k) {
    return std::any_of(printed.begin(), printed.end(), [&](const DesignPoint& p) {
      return same_design(p, predictions[k].candidate.point);
    });
  };
  for (std::size_t k = 0; k < predictions.size(); ++k) proposal.printed.push_back(is_printed(k));
  const auto& ranked = proposal.search.ranked;
  const auto untried = std::find_if(ranked.begin(), ranked.end(),
                                    [&](std::size_t k) { return !proposal.printed[k]; });
  proposal.next = predictions.at(untried == ranked.end() ? ranked.front() : *untried);
  return proposal;
}

std::string describe(LoopStop stop) {
  switch (stop) {
    case LoopStop::none:
      return "not stopped";
    case LoopStop::within_threshold:
      return "within the threshold";
    case LoopStop::no_closer_design:
      return "no design predicted closer";
    case LoopStop::round_limit:
      return "round limit";
  }
  return "";
}

LoopStop loop_stop(const std::vector<double>& measured_distances, double threshold, int max_rounds,
                   const Proposal* next) {
  if (!measured_distances.empty() && measured_distances.back() <= threshold)
    return LoopStop::within_threshold;
  if (next != nullptr && !measured_distances.empty()) {
    const double nearest_measured =
        *std::min_element(measured_distances.begin(), measured_distances.end());
    bool worth_a_print = false;
    for (std::size_t k = 0; k < next->search.evaluated.size(); ++k) {
      if (k < next->printed.size() && next->printed[k]) continue;
      worth_a_print = worth_a_print || next->search.evaluated[k].distance < nearest_measured ||
                      (k < next->chances.size() && next->chances[k] >= kLeastChanceWorthAPrint);
    }
    if (!worth_a_print) return LoopStop::no_closer_design;
  }
  if (static_cast<int>(measured_distances.size()) >= max_rounds) return LoopStop::round_limit;
  return LoopStop::none;
}

}  // namespace nibrig::model::design
