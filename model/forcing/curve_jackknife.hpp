// How firmly the data pin the tip and material curves: a delete-one-tool jackknife. Each printed
// tool (one print, measured on several surfaces: every exemplar with its tool id) is left out in
// turn and the rest refitted; the spread of the refitted curves gives the standard error of any
// statistic of them — a knot, or the difference between two tips at a knot.
//
// Tools, not exemplars, are the units left out: one print's spectra on six surfaces share that
// print's quirks (how the tip sits, its exact length), so its exemplars are not independent
// replicates of the curves, and leaving out one exemplar at a time would understate the error.
// With n tools the standard error is sqrt((n−1)/n · Σ(θ_i − θ̄)²) (Efron and Tibshirani, "An
// Introduction to the Bootstrap", 1993, Sec. 11.2; the grouped form: Sec. 11.5).
#pragma once

#include <functional>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "model/forcing/forcing_fit.hpp"

namespace nibrig::model::forcing {

// The fitted curves of one refit: knot values of ln t per tip and ln m per material.
struct CurveReplicate {
  std::map<double, std::vector<double>> tip;
  std::map<std::string, std::vector<double>> material;
};

struct CurveJackknife {
  CurveReplicate full;                      // the fit of every tool, whose errors these are
  std::vector<double> knot_frequencies_hz;  // of every curve's knots
  std::vector<std::string> tools;           // left out in turn, one replicate each
  std::vector<CurveReplicate> replicates;   // in the order of `tools`
  // Tools that could not be left out, each with why: without them a curve of the full fit is no
  // longer identifiable, or has no exemplar left. A jackknife over the others still describes
  // the rest of the data, but says nothing about those tools' own influence.
  std::vector<std::string> not_left_out;

  // Jackknife standard error of a statistic of the curves. Throws std::invalid_argument with
  // fewer than two replicates.
  double standard_error(const std::function<double(const CurveReplicate&)>& statistic) const;
  // The standard error of every knot of a tip's and of a material's curve.
  std::vector<double> tip_standard_errors(double tip_diameter_m) const;
  std::vector<double> material_standard_errors(const std::string& material) const;
};

// Refits once per tool of the exemplars (they need their responses). Throws like
// fit_forcing_model when the whole set cannot be fitted.
CurveJackknife jackknife_curves(std::span<const ForcingExemplar> exemplars,
                                const ForcingFitOptions& options = {});

}  // namespace nibrig::model::forcing
