// The design loop's decisions, round by round: a print is proposed, printed, measured on the rig
// and taken into the model (loop_refit.hpp, print_discrepancy.hpp), and the next is proposed from
// what the model now predicts, until a print is as close to the target as the space can tell.
//
// Which print next (NextPrintRule): the plain rule prints the predicted optimum, the design whose
// corrected placement lies nearest the target. The default prints the design likeliest to land
// within the threshold: where the model is unsure, a design whose mean is a little farther may
// have the better chance, and its measurement teaches the model most where it matters. The loop's
// simulated world (tests/model/design/design_loop_world_test.cpp) compares the two.
//
// When it stops (LoopStop): a measured print within the threshold; the model, corrected by the
// prints, predicting no design of the range nearer than the nearest measured print; or the round
// limit.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "model/design/design_search.hpp"
#include "model/design/print_discrepancy.hpp"
#include "model/io/catalog_file.hpp"
#include "model/space/descriptor_map.hpp"
#include "model/space/judgment_model.hpp"

namespace nibrig::model::design {

enum class NextPrintRule { predicted_optimum, likeliest_within_threshold };
inline constexpr NextPrintRule kDefaultNextPrintRule = NextPrintRule::likeliest_within_threshold;

// "optimum", "likeliest"; parse_next_print_rule throws std::invalid_argument naming both.
std::string rule_name(NextPrintRule rule);
NextPrintRule parse_next_print_rule(const std::string& name);

// The distance a listener tells from none: with the target itself as the reference, the print is
// judged the closer of the two (the target, the print) in a quarter of the triplets, the 75 % of a
// two-alternative task's conventional threshold. Solved on the space's own judgment model without
// its lapse (inattention is not the sound's), with the typical noise of a tool never judged. For
// the paper's probit at s = 2/3 that is 1.01 units.
double just_noticeable_distance(const space::JudgmentModel& model, std::size_t dims);

// The descriptors (the map's, in its order) of a measured pairing, as predicted_descriptors gives a
// prediction's. Throws io::FormatError when the pairing lacks one (naming it).
Eigen::VectorXd measured_descriptors(const space::DescriptorMap& map, const io::Pairing& pairing);

struct LoopContext {
  const space::DescriptorMap* map = nullptr;
  space::Placement target;
  double threshold = 1.0;             // the distance a print must come within
  Eigen::MatrixXd measurement_noise;  // a measurement's descriptor noise (the discrepancy's R)
  int samples = 2000;
  std::uint64_t seed = 1;
};

// A design as the loop predicts it: the prediction's descriptors corrected by the prints so far,
// placed with the correction's uncertainty. `candidate.distance` is between the means;
// `chance_within` is the chance its measured placement lands within the threshold of the
// target's, over the corrected prediction's error and the measurement's noise.
struct LoopPrediction {
  Candidate candidate;
  Eigen::VectorXd descriptors;
  double chance_within = 0.0;
};

LoopPrediction predict_in_loop(const LoopContext& context, const PrintDiscrepancy& discrepancy,
                               const PredictedTool& tool);

// A measured print: its placement (as any measured tool's) and distance to the target.
struct MeasuredPlacement {
  Eigen::VectorXd descriptors;
  space::Placement placement;
  double distance = 0.0, distance_sd = 0.0;
};
MeasuredPlacement place_measured(const LoopContext& context, const io::Pairing& pairing);

// The range search for the next print under `rule` (or, when `candidates` is not empty, each of
// those designs alone: a lab that can print only some, or prints that exist already): every
// candidate carries its corrected distance, and `score` the rule's key (the distance, or minus the
// chance). The next print is its best that is none of `printed` (printed again, a design would
// only measure the same: the loop is for what it has not tried).
struct Proposal {
  SearchResult search;
  LoopPrediction next;
  std::vector<double> chances;  // per evaluated candidate
  std::vector<bool> printed;    // per evaluated candidate: a design printed already
};
Proposal propose_next_print(const LoopContext& context, const PrintDiscrepancy& discrepancy,
                            const Predict& predict, const RangeSearchOptions& range,
                            NextPrintRule rule, const std::vector<DesignPoint>& candidates = {},
                            const std::vector<DesignPoint>& printed = {});

enum class LoopStop { none, within_threshold, no_closer_design, round_limit };
// "within the threshold", "no design predicted closer", "round limit".
std::string describe(LoopStop stop);

// Below this chance of landing within the threshold a print is not worth its hours of printing and
// measuring: the loop's policy, not a measured number.
inline constexpr double kLeastChanceWorthAPrint = 0.1;

// Why the loop stops after the prints of `printed` measured at `measured_distances` (one per round,
// in order), given the next proposal (none yet: only the measured prints' reasons). Within the
// threshold first; then no design predicted closer: of the designs not printed yet, none predicted
// nearer than the nearest measured print and none with kLeastChanceWorthAPrint of landing within
// the threshold (or none left); then the round limit.
LoopStop loop_stop(const std::vector<double>& measured_distances, double threshold, int max_rounds,
                   const Proposal* next);

}  // namespace nibrig::model::design
