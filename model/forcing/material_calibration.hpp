// A new material's curve m_μ(f) calibrated from a few prints of it measured on surfaces a fitted
// forcing model knows. Everything else is held (F_S, the tip curves, each print's simulated |H|),
// so in log amplitude ln M − ln|H| − ln F_S − ln t_d = ln m_μ(f) + noise, and the knot values of
// ln m_μ are a linear least-squares fit, as in the full fit (forcing_fit.hpp), of that curve alone.
//
// Uncertainty: one exemplar's residuals (a print on a surface) are correlated over its bins and
// speeds (the spectra are smoothed over five bins; one print sits one way on one surface), so the
// bins are not independent replicates and σ²(XᵀX)⁻¹ would count thousands of them. Exemplars are
// the units: the covariance is the cluster-robust (sandwich) one, an exemplar per cluster, scaled
// by G/(G−1) for G of them (Cameron and Miller, "A Practitioner's Guide to Cluster-Robust
// Inference", J. Human Resources 50(2), 2015, Sec. II-C, VI). With all exemplars on one grid it is
// the spread of the per-exemplar curves over √G, with G − 1 degrees of freedom.
//
// Exemplars of one print share that print (and its tip curve, held from other materials): on the
// catalog, DM95 calibrated from its 1 mm prints alone and from its 4 mm prints alone differ by
// ~1 dB at most knots, 2-3 of those standard errors. So a print's own curve varies about the
// material's by τ beyond its exemplars' noise, a one-way random effect (Searle, Casella and
// McCulloch, "Variance Components", 1992, Sec. 3.5: the ANOVA estimator); τ² is the prints' curves'
// spread minus what the within part explains of it, pooled over the knots (two prints give one
// degree of freedom per knot) and floored at 0; τ²/P adds to each knot's variance. With P prints
// that part has P − 1 degrees of freedom: with two prints the error of the error is large, and the
// interval's t quantile (degrees_of_freedom) says so. Left out: the held F_S's own error.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "model/forcing/forcing_fit.hpp"
#include "model/forcing/forcing_model.hpp"

namespace nibrig::model::forcing {

struct MaterialCalibration {
  ForcingModel model;  // the input, with the material's curve and its standard errors added
  std::string material;
  std::vector<double> log_gain, log_gain_se;  // per knot of the model, natural log
  std::vector<double> log_gain_within_se;     // the exemplars' part of log_gain_se alone
  std::size_t exemplars = 0, prints = 0;      // prints: distinct tool ids
  // The spread of one print's curve about the material's beyond its exemplars' noise (ln, pooled
  // over the knots): 0 from one print, or when the prints agree within that noise.
  double print_log_gain_sd = 0.0;
  // Of a knot's t-interval (Welch-Satterthwaite over the two parts, knots averaged): exemplars − 1
  // when the prints agree, towards prints − 1 when they do not.
  double degrees_of_freedom = 0.0;
  // How far the calibrated model is from the prints it was calibrated on (dB RMS), and per print.
  double residual_rms_db = 0.0;
  std::vector<ExemplarFit> print_fits;
};

// `prints` are exemplars of `material` with their responses, on surfaces and with tips the model
// has curves for, on its grid. Throws std::invalid_argument naming the print or the material: a
// print of another material, on an unknown surface or tip, off the grid; fewer than two exemplars
// (one gives a curve but no spread to tell its error); the material already in the model (a
// calibration adds a material, it never replaces one fitted with the catalog: choose a new name);
// and std::runtime_error when the prints leave a knot undetermined (no bins near it).
MaterialCalibration calibrate_material(const ForcingModel& model,
                                       std::span<const ForcingExemplar> prints,
                                       const std::string& material);

}  // namespace nibrig::model::forcing
