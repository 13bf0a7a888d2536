// The fit of the paper's Eq. 10: surface forcing F_S, tip curves t and material curves m from the
// measured spectra of printed tools whose responses H are simulated (forcing_model.hpp for the
// model itself).
//
// Objective: Σ over exemplars, frequency bins and speeds of (ln M − ln(|H|·F·t·m))². In log
// amplitude every bin weighs by its relative error, so the quiet high-frequency bins count as much
// as the loud resonances (the paper's L2 of raw amplitudes would be decided by a few peaks), and
// the product becomes a sum: with the Hermite curves linear in their knot values the whole problem
// is linear least squares. Measured amplitudes ≤ 0 have no logarithm and are skipped (counted in
// ForcingModel::skipped_nonpositive).
//
// Gauge: t·m·F can trade constants, and whole curves c(f), among themselves (t_d·c, F_S/c fit the
// same data). Pinned by ln t(reference tip) ≡ 0 and ln m(reference material) ≡ 0, by default the
// 2 mm tip and "vero" (VeroClear): F_S is then the forcing the 2 mm VeroClear tool sees, and every
// other curve is a gain relative to that tool.
//
// Solve: F is free per cell (surface, speed, bin), so for fixed knots its optimum is exact: ln F of
// a cell is the mean over that cell's exemplars of ln M − ln|H| − ln t − ln m. Substituting it
// leaves, for the knots alone, a least-squares problem whose rows are centred within each cell;
// its normal equations are small and dense (11 knots per free curve) and solved by Eigen's
// ColPivHouseholderQR with a rank check, then F is recovered. A cell with one exemplar fits it
// exactly and carries no information about the knots (a tool alone on its surface says nothing
// about its tip or material).
#pragma once

#include <span>
#include <string>
#include <utility>
#include <vector>

#include "model/forcing/forcing_model.hpp"
#include "model/io/velocity_spectrum.hpp"

namespace nibrig::model::forcing {

// One measured tool on one surface with its simulated response.
struct ForcingExemplar {
  std::string tool, surface;  // catalog ids
  std::string material;       // the catalog's material name
  double tip_diameter_m = 0.0;
  io::VelocitySpectrum measured;
  std::vector<double> response_magnitude;  // |H| at measured.frequencies_hz, (m/s²)/N
  // A print of a mix (a design loop's print): each material's fraction, ln m being their weighted
  // sum as in a prediction. Empty: `material` alone.
  std::vector<std::pair<std::string, double>> mix;
  // Its tip is interpolated between the other exemplars' tips as a prediction's is (ln t linear in
  // the diameter between the two around it), not given a curve of its own: one print at 2.6 mm
  // says too little to fit a tip curve, but constrains the ones beside it.
  bool tip_interpolated = false;
};

struct ForcingFitOptions {
  std::vector<double> knot_frequencies_hz;  // empty: default_knot_frequencies() (0, 50, …, 500 Hz)
  double reference_tip_diameter_m = 0.002;
  std::string reference_material = "vero";
};

// Why these exemplars cannot be fitted, one sentence per problem (empty when they can): a tip or
// material curve that the data do not separate from the surface forcing and the other curves
// (e.g. it appears only on a surface where no other tool was measured), an exemplar whose spectrum
// or response does not match the others' grid, no exemplars. Checked per knot on the structure of
// the data (which tool shares a surface with which), so it names the culprit; the fit checks the
// numerical rank as well.
std::vector<std::string> fit_problems(std::span<const ForcingExemplar> exemplars,
                                      const ForcingFitOptions& options = {});

// Throws std::invalid_argument listing fit_problems() when there are any, and std::runtime_error
// when the normal equations are still rank deficient (frequencies that leave a knot without data).
ForcingModel fit_forcing_model(std::span<const ForcingExemplar> exemplars,
                               const ForcingFitOptions& options = {});

}  // namespace nibrig::model::forcing
