// The data-driven forcing model of the paper's Sec. 5.2, as fitted (forcing_fit.hpp): a tool Ψ
// with tip diameter d and material μ on surface S is predicted to measure
//   M(f, v) = |H_Ψ(f)| · F_S(f, v) · t_d(f) · m_μ(f)
// with H_Ψ its simulated frequency response (tip force → sensor acceleration), F_S the surface's
// forcing (N, free per frequency bin and speed), and t, m piecewise cubic Hermite curves of the log
// gain (hermite_curve.hpp). The reference tip and material have t ≡ m ≡ 1 (log gain 0): F_S is the
// forcing that the reference tool (2 mm VeroClear) sees.
#pragma once

#include <cstddef>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "model/forcing/descriptor_error.hpp"
#include "model/io/velocity_spectrum.hpp"

namespace nibrig::model::forcing {

// How well the model fits one exemplar: RMS over its bins and speeds of 20·log10(model/measured).
struct ExemplarFit {
  std::string tool, surface;
  double rms_db = 0.0;
};

struct ForcingModel {
  std::vector<double> knot_frequencies_hz;
  // Knot values of the natural-log gains, one curve per tip diameter (m) and per catalog material.
  // The references hold zeros.
  std::map<double, std::vector<double>> tip_log_gain;
  std::map<std::string, std::vector<double>> material_log_gain;
  double reference_tip_diameter_m = 0.002;
  std::string reference_material = "vero";

  std::vector<double> frequencies_hz;  // the exemplars' common grid
  std::vector<double> speeds_m_s;
  // F_S[speed][frequency] in N (peak amplitude of the force at that bin), per surface id.
  std::map<std::string, std::vector<std::vector<double>>> surface_forcing;

  // Fit quality: the RMS of 20·log10(model/measured) over every observation, per exemplar, how
  // many observations were used and how many measured amplitudes were skipped for being ≤ 0 (no
  // logarithm).
  double residual_rms_db = 0.0;
  std::vector<ExemplarFit> exemplar_fits;
  std::size_t observations = 0;
  std::size_t skipped_nonpositive = 0;
  // Where the data and responses came from and what was assumed, written with the model.
  std::vector<std::string> notes;
  // How far the descriptors of tools this model predicts were from the measured ones when each
  // exemplar was held out (held_out_descriptor_errors), weighted by the named threshold curve:
  // the error a predicted tool's descriptors carry. Empty for a model fitted without them (a file
  // written before they existed): its predictions are then placed as if their descriptors were
  // measured.
  std::vector<DescriptorError> held_out_descriptor_errors;
  std::string descriptor_error_threshold;
  // Standard errors of what was calibrated from a few prints after the fit
  // (material_calibration.hpp, surface_calibration.hpp): per knot of ln m for a calibrated
  // material, per cell [speed][frequency] of ln F for a calibrated surface. Curves and surfaces
  // fitted with the catalog have none here (their errors are the jackknife's, computed apart).
  std::map<std::string, std::vector<double>> material_log_gain_se;
  std::map<std::string, std::vector<std::vector<double>>> surface_log_forcing_se;

  std::size_t exemplar_count() const { return exemplar_fits.size(); }

  // ln t_d(f), ln m_μ(f) at any frequency within the knots. Throws std::invalid_argument for a tip
  // diameter (matched by same_tip) or material the model has no curve for, naming those it has,
  // and for a frequency outside the knots.
  double tip_log_gain_at(double tip_diameter_m, double frequency_hz) const;
  double material_log_gain_at(const std::string& material, double frequency_hz) const;

  // The predicted measurement of a tool with response magnitude |H| (m/s² per N, one value per
  // model frequency) on `surface`: amplitudes in m/s² on the model's frequencies and speeds.
  // Throws std::invalid_argument for an unknown surface, tip or material, a response of the wrong
  // length, or a negative or non-finite |H|.
  io::VelocitySpectrum predict(std::span<const double> response_magnitude,
                               const std::string& surface, double tip_diameter_m,
                               const std::string& material) const;

  // The standard error of ln m_μ(f) and of ln F_S at a model speed and frequency index: 0 where
  // nothing was calibrated. Between knots the knots' errors are combined as Σ|w_k|·se_k, exact
  // when they move together and an upper bound otherwise (only per-knot errors are stored).
  double material_log_gain_se_at(const std::string& material, double frequency_hz) const;
  double surface_log_forcing_se_at(const std::string& surface, std::size_t speed,
                                   std::size_t frequency) const;
  // The standard error of ln M predicted for `material` on `surface` at a model speed and
  // frequency index: the two calibrations are independent, so their variances add.
  double prediction_log_se(const std::string& surface, const std::string& material,
                           std::size_t speed, std::size_t frequency) const;

  // The curve of a tip diameter (same_tip) or material; throws like the *_at functions.
  const std::vector<double>& tip_curve(double tip_diameter_m) const;
  const std::vector<double>& material_curve(const std::string& material) const;
};

// 20·log10(e)·x: a natural-log gain in dB.
double log_gain_to_db(double log_gain);

// Tip diameters come from files in millimetres: two within 1 µm are the same tip.
bool same_tip(double a_m, double b_m);
// "2 mm", "0.5 mm".
std::string tip_label(double diameter_m);

}  // namespace nibrig::model::forcing
