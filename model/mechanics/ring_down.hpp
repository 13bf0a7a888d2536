// The ring-down test of Sec. 5.1: a clamped body whose tip is pushed aside by a preload and
// released; its sensor then records the modes decaying. Simulates that test from a ModalModel and
// fits Young's modulus and the Rayleigh stiffness coefficient to a measured trace (the paper's
// Fig. 11: 0.45 GPa and 1.25e-3 s for its VeroClear bar).
#pragma once

#include <cstddef>
#include <vector>

#include "model/io/acceleration_trace.hpp"
#include "model/mechanics/material_table.hpp"
#include "model/modal/modal_model.hpp"

namespace nibrig::model::mechanics {

// Sensor acceleration (m/s²) sampled at `sample_rate` Hz for `samples` samples, with the release at
// `release_time` seconds (zero before it). Before release the body rests in the static deflection
// of a force at the tip along the tip direction, scaled so that the tip moves by `preload` metres:
// in modes, q_i(0) = b_i P / ω_i² with P = preload / Σ b_j²/ω_j², the modal truncation of K⁻¹f.
// Each mode then evolves by its exact free transition, whatever its damping.
std::vector<double> simulate_release(const modal::ModalModel& model, double preload,
                                     double sample_rate, std::size_t samples,
                                     double release_time = 0.0);

// Adds Gaussian sensor noise of `relative_rms` times the trace's RMS (seeded): how a simulated trace
// stands in for a measured one where the paper publishes values but not its recording.
void add_relative_noise(std::vector<double>& trace, double relative_rms, unsigned seed);

// The same body at another stiffness: K scales with E and M does not, so ω_i scales with
// √(modulus_ratio) while the mass-normalised shapes (b_i, c_i) stay; the damping ratios follow
// from `damping`. For a body of several materials every modulus is scaled by the same ratio.
modal::ModalModel rescale_modulus(const modal::ModalModel& reference, double modulus_ratio,
                                  const RayleighDamping& damping);

struct RingDownOptions {
  double reference_modulus = 0.0;  // Pa: the E at which the reference ModalModel was computed
  double preload = 0.05;           // m: the paper preloads its bar by 5 cm
  double mass_damping = 0.0;       // α (1/s), held fixed: the paper uses stiffness damping only
  // Fit an amplitude factor (sensor gain, misaligned axis, an unknown preload); when false, the
  // trace must be calibrated m/s² along the design's sensor axis.
  bool fit_gain = true;
};

struct RingDownFit {
  double youngs_modulus = 0.0;      // Pa
  double rayleigh_stiffness = 0.0;  // λ, s
  double release_time = 0.0;        // s from the first sample of the trace
  double gain = 1.0;                // measured / simulated amplitude
  double relative_residual = 0.0;  // ‖measured − fitted‖ / ‖measured‖ over the whole trace
  double first_mode_hz = 0.0;      // of the fitted model
  double first_mode_damping_ratio = 0.0;
  int evaluations = 0;         // simulations run
  std::vector<double> fitted;  // the fitted trace, sample for sample with the measured one
};

// Coarse search over modulus and first-mode damping on magnitude spectra (insensitive to release
// time and gain), release time from the cross-correlation, then Levenberg-Marquardt on
// (ln E, ln λ, release time) with the gain solved in closed form at every step, and last
// Gauss-Newton on all four together, so that the fit is the least-squares one whose uncertainty
// ring_down_uncertainty.hpp gives. Throws
// std::invalid_argument for an empty model, a non-positive reference modulus or preload, or a trace
// without signal.
RingDownFit fit_ring_down(const modal::ModalModel& reference, const RingDownOptions& options,
                          const io::AccelerationTrace& trace);

}  // namespace nibrig::model::mechanics
