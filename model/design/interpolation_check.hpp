// The check of Sec. 5.3 (Fig. 14): predict measured designs that the fit never saw, by
// interpolation between the designs it did see, and compare with the no-interpolation baseline.
// Here the held-out designs are every exemplar with one tip diameter (e.g. all 2 mm tools): the
// model is fitted without them (the reference tip moved to the smallest remaining one), and each is
// predicted with its own simulated response and the tip curve interpolated between the fitted
// neighbours. The baseline is the same prediction with a neighbour's tip curve instead — the
// paper's grey lines, a simulation that does not interpolate the parameters — once per neighbour.
// Beside it, the neighbours' own measurements as predictions (no model at all).
#pragma once

#include <array>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "model/design/no_interpolation_baseline.hpp"
#include "model/forcing/curve_jackknife.hpp"
#include "model/forcing/forcing_fit.hpp"

namespace nibrig::model::design {

struct InterpolatedPrediction {
  std::string tool, surface, material;
  double tip_diameter_m = 0.0;
  // Why it could not be predicted (its surface or material is in no training exemplar); empty
  // when it was, and then the comparison below is set.
  std::string not_predictable;
  // The interpolated prediction and the two baselines (no_interpolation_corners: the smaller and
  // the larger neighbour's tip curve, in that order) against the measurement, overall and per
  // speed.
  InterpolationComparison comparison;
  // What a designer without the model would do: take a measured neighbour on the same surface as
  // the prediction — for a held-out tip the same material's smaller and larger fitted tip, for a
  // held-out material (material_hold_out.hpp) the same tip in the mix's first and second material
  // (negative when that neighbour was not measured).
  std::array<double, 2> measured_neighbour_rms_db{-1.0, -1.0};
};

// Predicts the held-out exemplar `held` as `point` (its own response and surface) with `model`,
// against the no-interpolation baselines around the point, and against the exemplars of `all` that
// `is_neighbour[0]` and `is_neighbour[1]` pick, taken as they are. Not predictable, saying why,
// when the model lacks its surface.
using NeighbourTest = std::function<bool(const forcing::ForcingExemplar&)>;
InterpolatedPrediction predict_held_out(const forcing::ForcingModel& model,
                                        const forcing::ForcingExemplar& held,
                                        const DesignPoint& point,
                                        std::span<const forcing::ForcingExemplar> all,
                                        const std::array<NeighbourTest, 2>& is_neighbour);

struct TipHoldOut {
  forcing::ForcingModel model;  // fitted without the held-out tip (reference: the smallest tip)
  double lower_tip_m = 0.0, upper_tip_m = 0.0;      // the fitted neighbours interpolated between
  std::vector<InterpolatedPrediction> predictions;  // one per held-out exemplar, in input order
};

// The hold-out in a few numbers, over the predictable tools: how many beat both baselines, the
// largest |RMS error − a baseline's|, and against the measured neighbours (every neighbour that
// was measured is one comparison) how often the prediction is closer and the mean of each side.
// Per speed (the model's speeds), the mean RMS error of the predictions and of each baseline
// (in the order of no_interpolation_corners; the hold-outs have two) over the predicted tools, and
// on how many the prediction beats every baseline at that speed.
struct HoldOutSummary {
  int predicted = 0, beats_every_baseline = 0;
  double widest_baseline_gap_db = 0.0;
  int compared_with_measured = 0, closer_than_measured = 0;
  double mean_predicted_db = 0.0, mean_measured_db = 0.0;  // over those comparisons
  std::vector<double> mean_predicted_db_by_speed;
  std::vector<std::vector<double>> mean_baseline_db_by_speed;  // [baseline][speed]
  std::vector<int> beats_every_baseline_by_speed;
};
HoldOutSummary summarize(std::span<const InterpolatedPrediction> predictions);
inline HoldOutSummary summarize(const TipHoldOut& held) { return summarize(held.predictions); }

// Exemplars need their responses (forcing::attach_responses). Throws std::invalid_argument when
// no exemplar has `tip_m`, when it is not strictly between two other fitted tips, or when the
// training set cannot be fitted (forcing::fit_problems, joined).
TipHoldOut hold_out_tip(std::span<const forcing::ForcingExemplar> exemplars, double tip_m);

// What the data can resolve of that check, from a fit of every exemplar (held-out tip included):
// per knot, the tip effect between the neighbours (ln t_upper − ln t_lower) and how far the
// held-out tip's own curve lies from the straight line between them (ln t_held − the
// interpolation) — each with its delete-one-tool jackknife standard error (curve_jackknife.hpp).
// Both are differences of tip curves, so the choice of reference tip does not change them. When
// the deviation is within its error, interpolation is as good as the data can tell; when the
// effect is within its error, nothing — interpolated or not — can be told apart from a neighbour.
struct TipResolution {
  double tip_m = 0.0, lower_tip_m = 0.0, upper_tip_m = 0.0;
  std::vector<double> knot_frequencies_hz;
  std::vector<double> effect, effect_se;        // ln t_upper − ln t_lower, per knot
  std::vector<double> deviation, deviation_se;  // ln t_held − interpolation, per knot
  std::size_t tools = 0;                        // jackknife replicates
  // Knots where the effect, or the deviation, exceeds twice its standard error.
  std::size_t effect_resolved_knots() const;
  std::size_t deviation_resolved_knots() const;
};

// How many of the values exceed twice their standard error (value and se of equal length).
std::size_t knots_beyond_two_errors(const std::vector<double>& value,
                                    const std::vector<double>& se);

// From a jackknife of every exemplar (forcing::jackknife_curves: its full fit and replicates).
// Throws std::invalid_argument when `tip_m` has no curve in the full fit or is not strictly
// between two fitted tips, or when fewer than two tools could be left out.
TipResolution tip_resolution(const forcing::CurveJackknife& jackknife, double tip_m);

}  // namespace nibrig::model::design
