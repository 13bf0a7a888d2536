#include "model/design/interpolation_check.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>

#include "model/design/predicted_tool.hpp"
#include "model/forcing/leave_one_out.hpp"

namespace nibrig::model::design {

TipHoldOut hold_out_tip(std::span<const forcing::ForcingExemplar> exemplars, double tip_m) {
  std::vector<forcing::ForcingExemplar> training;
  std::vector<const forcing::ForcingExemplar*> held_out;
  std::set<double> tips;
  for (const auto& e : exemplars) {
    if (forcing::same_tip(e.tip_diameter_m, tip_m)) {
      held_out.push_back(&e);
    } else {
      training.push_back(e);
      tips.insert(e.tip_diameter_m);
    }
  }
  const std::string what = "holding out the " + forcing::tip_label(tip_m) + " tips";
  if (held_out.empty()) throw std::invalid_argument(what + ": no exemplar has that tip");
  const auto upper = tips.upper_bound(tip_m);
  if (tips.empty() || upper == tips.begin() || upper == tips.end())
    throw std::invalid_argument(what + ": the other tips do not lie on both sides of it");
  const double lower_tip = *std::prev(upper), upper_tip = *upper;

  forcing::ForcingFitOptions options;
  options.reference_tip_diameter_m = *tips.begin();
  if (const auto problems = forcing::fit_problems(training, options); !problems.empty()) {
    std::string text = what + ": the rest cannot be fitted:";
    for (const auto& p : problems) text += " " + p + ";";
    throw std::invalid_argument(text);
  }
  TipHoldOut out;
  out.model = forcing::fit_forcing_model(training, options);
  out.lower_tip_m = lower_tip;
  out.upper_tip_m = upper_tip;
  for (const forcing::ForcingExemplar* e : held_out) {
    const auto same_material_with_tip = [e](double tip) -> NeighbourTest {
      return [e, tip](const forcing::ForcingExemplar& x) {
        return x.material == e->material && forcing::same_tip(x.tip_diameter_m, tip);
      };
    };
    out.predictions.push_back(predict_held_out(
        out.model, *e, DesignPoint{{{e->material, 1.0}}, e->tip_diameter_m}, exemplars,
        {same_material_with_tip(lower_tip), same_material_with_tip(upper_tip)}));
  }
  return out;
}

InterpolatedPrediction predict_held_out(const forcing::ForcingModel& model,
                                        const forcing::ForcingExemplar& held,
                                        const DesignPoint& point,
                                        std::span<const forcing::ForcingExemplar> all,
                                        const std::array<NeighbourTest, 2>& is_neighbour) {
  InterpolatedPrediction r;
  r.tool = held.tool;
  r.surface = held.surface;
  r.material = held.material;
  r.tip_diameter_m = held.tip_diameter_m;
  if (model.surface_forcing.count(held.surface) == 0) {
    r.not_predictable = "no other tool was measured on " + held.surface;
    return r;
  }
  for (const auto& share : point.mix)
    if (model.material_log_gain.count(share.material) == 0) {
      r.not_predictable = "no other tool is of " + share.material;
      return r;
    }
  r.comparison =
      compare_with_baselines(model, point, held.surface, held.response_magnitude, held.measured);
  for (const auto& other : all)
    for (std::size_t k = 0; k < 2; ++k)
      if (other.surface == held.surface && &other != &held && is_neighbour[k](other))
        r.measured_neighbour_rms_db[k] =
            forcing::log_spectrum_error(other.measured, held.measured).rms_db;
  return r;
}

HoldOutSummary summarize(std::span<const InterpolatedPrediction> predictions) {
  HoldOutSummary s;
  for (const auto& r : predictions) {
    if (!r.not_predictable.empty()) continue;
    ++s.predicted;
    const auto& c = r.comparison;
    const std::size_t speeds = c.interpolated.rms_db_by_speed.size();
    if (s.mean_predicted_db_by_speed.empty()) {
      s.mean_predicted_db_by_speed.assign(speeds, 0.0);
      s.mean_baseline_db_by_speed.assign(c.baselines.size(), std::vector<double>(speeds, 0.0));
      s.beats_every_baseline_by_speed.assign(speeds, 0);
    }
    if (s.mean_baseline_db_by_speed.size() != c.baselines.size() ||
        s.mean_predicted_db_by_speed.size() != speeds)
      throw std::invalid_argument(r.tool + " on " + r.surface +
                                  ": its comparison has other baselines or speeds than the first");
    for (std::size_t v = 0; v < speeds; ++v) {
      const double e = c.interpolated.rms_db_by_speed[v];
      s.mean_predicted_db_by_speed[v] += e;
      bool beats = !c.baselines.empty();
      for (std::size_t b = 0; b < c.baselines.size(); ++b) {
        const double baseline = c.baselines[b].error.rms_db_by_speed.at(v);
        s.mean_baseline_db_by_speed[b][v] += baseline;
        beats = beats && e < baseline;
      }
      s.beats_every_baseline_by_speed[v] += beats;
    }
    s.beats_every_baseline += r.comparison.beats_every_baseline();
    const double rms_db = r.comparison.interpolated.rms_db;
    for (const auto& baseline : r.comparison.baselines)
      s.widest_baseline_gap_db =
          std::max(s.widest_baseline_gap_db, std::abs(rms_db - baseline.error.rms_db));
    for (double measured : r.measured_neighbour_rms_db) {
      if (measured < 0) continue;
      ++s.compared_with_measured;
      s.closer_than_measured += rms_db < measured;
      s.mean_predicted_db += rms_db;
      s.mean_measured_db += measured;
    }
  }
  if (s.compared_with_measured > 0) {
    s.mean_predicted_db /= s.compared_with_measured;
    s.mean_measured_db /= s.compared_with_measured;
  }
  for (auto& m : s.mean_predicted_db_by_speed) m /= s.predicted;
  for (auto& baseline : s.mean_baseline_db_by_speed)
    for (auto& m : baseline) m /= s.predicted;
  return s;
}

std::size_t knots_beyond_two_errors(const std::vector<double>& value,
                                    const std::vector<double>& se) {
  std::size_t n = 0;
  for (std::size_t k = 0; k < value.size(); ++k) n += std::abs(value[k]) > 2 * se.at(k);
  return n;
}

std::size_t TipResolution::effect_resolved_knots() const {
  return knots_beyond_two_errors(effect, effect_se);
}

std::size_t TipResolution::deviation_resolved_knots() const {
  return knots_beyond_two_errors(deviation, deviation_se);
}

TipResolution tip_resolution(const forcing::CurveJackknife& jackknife, double tip_m) {
  const auto& full = jackknife.full.tip;
  std::vector<double> tips;
  for (const auto& [d, knots] : full) tips.push_back(d);
  const std::string what = "resolving the " + forcing::tip_label(tip_m) + " tip";
  const auto held =
      std::find_if(tips.begin(), tips.end(), [&](double d) { return forcing::same_tip(d, tip_m); });
  if (held == tips.end()) throw std::invalid_argument(what + ": the fit has no curve for it");
  if (held == tips.begin() || held + 1 == tips.end())
    throw std::invalid_argument(what + ": the other tips do not lie on both sides of it");

  TipResolution out;
  out.tip_m = *held;
  out.lower_tip_m = *(held - 1);
  out.upper_tip_m = *(held + 1);
  out.knot_frequencies_hz = jackknife.knot_frequencies_hz;
  const double w = (out.tip_m - out.lower_tip_m) / (out.upper_tip_m - out.lower_tip_m);
  const auto effect_at = [&](const std::map<double, std::vector<double>>& t, std::size_t k) {
    return t.at(out.upper_tip_m)[k] - t.at(out.lower_tip_m)[k];
  };
  const auto deviation_at = [&](const std::map<double, std::vector<double>>& t, std::size_t k) {
    return t.at(out.tip_m)[k] - ((1 - w) * t.at(out.lower_tip_m)[k] + w * t.at(out.upper_tip_m)[k]);
  };
  out.tools = jackknife.replicates.size();
  for (std::size_t k = 0; k < out.knot_frequencies_hz.size(); ++k) {
    out.effect.push_back(effect_at(full, k));
    out.deviation.push_back(deviation_at(full, k));
    out.effect_se.push_back(jackknife.standard_error(
        [&](const forcing::CurveReplicate& r) { return effect_at(r.tip, k); }));
    out.deviation_se.push_back(jackknife.standard_error(
        [&](const forcing::CurveReplicate& r) { return deviation_at(r.tip, k); }));
  }
  return out;
}

}  // namespace nibrig::model::design
