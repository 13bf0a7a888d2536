// Coulomb friction from the rig's tangential-force recordings: where the tip is in sliding contact,
// the coefficient μ = F_t / F_n with an honest confidence interval, and how μ drifts with speed.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace nibrig::model::measure {

// Sliding contact [begin, end) in samples, and the two force levels the detection found.
struct ContactRegion {
  std::size_t begin = 0;
  std::size_t end = 0;
  double baseline_N = 0.0;  // force before/after contact (sensor offset)
  double plateau_N = 0.0;   // typical force in contact
};

// Robust two-level detection. The levels come from the record itself: split at the midpoint of its
// 2nd and 98th percentiles, the baseline is the median below and the plateau the median above. The
// force, smoothed over 50 ms, enters contact above baseline + 50 % of the step and leaves below
// baseline + 25 % (hysteresis); gaps under 0.5 s are bridged and contacts under 1 s ignored; the
// longest contact wins. Its edges are then walked outwards to where the smoothed force is within 10
// % of the step from the baseline, so `begin` is where the force starts to rise. Real-tool files of
// the paper begin contact 10-21 s in, the others 3-4 s in; some end with the force falling as the
// turntable stops. Throws std::invalid_argument on a bad rate or fewer than 2 s of samples,
// std::runtime_error when no contact stands out (step under 5 % of the larger level, or no run long
// enough).
ContactRegion detect_contact(std::span<const double> tangential_force_N, double sample_rate_hz);

// How the turntable speed is taken to vary over the recording. An ASSUMPTION carried over from the
// paper's code, which plots each file against linspace(0, 255 mm/s) over all its samples: the files
// store no speed. Speed at sample i of n: start + (end - start) · i / (n - 1).
struct SweepAssumption {
  double start_speed_m_s = 0.0;
  double end_speed_m_s = 0.255;
  std::size_t speed_bins = 8;
};

struct FrictionFit {
  double mu = 0.0;  // mean of F_t / F_n over the analysed part of the contact
  // 95 % confidence interval of mu. The force is sampled at 1 kHz but wanders over seconds, so the
  // samples are far from independent and the naive SE (σ/√n) would be several times too small. The
  // SE here is σ_r sqrt(τ/n), with σ_r and the integrated autocorrelation time τ (Sokal window, see
  // effective_sample_size.hpp) of the residuals about the linear speed trend: the trend is a
  // deterministic function of the sweep, the residuals are the noise. Interval: mu ± 1.96 SE (the
  // effective sample size n/τ is in the hundreds or more, where Student's t adds < 1 %).
  double mu_ci_low = 0.0;
  double mu_ci_high = 0.0;
  ContactRegion contact;
  // Analysed part [analysis_begin, analysis_end): the contact less 1 s at each end, so that the
  // loading ramp, the static-friction peak at the start of sliding and the unloading are not
  // averaged in.
  std::size_t analysis_begin = 0;
  std::size_t analysis_end = 0;
  std::size_t samples = 0;         // analysis_end - analysis_begin
  double effective_samples = 0.0;  // samples / τ
  // The analysed part cut into speed_bins equal time (hence speed) pieces: mean speed, mean μ and
  // its 95 % interval (the piece's residual variance with the whole part's τ).
  std::vector<double> speeds_m_s, mu_by_speed, mu_by_speed_ci_low, mu_by_speed_ci_high;
  double speed_slope_per_m_s =
      0.0;  // least-squares slope of μ(t) on speed(t) over the analysed part
};

// normal_load_N > 0 and finite, sweep.speed_bins >= 1 and each bin at least 2 samples, else
// std::invalid_argument; detection failures as detect_contact.
FrictionFit fit_coulomb_friction(std::span<const double> tangential_force_N, double sample_rate_hz,
                                 double normal_load_N, const SweepAssumption& sweep);

// The paper's estimate, for comparison: mean of the force over rows 5000..20000 of the file (MATLAB
// d(5e3:20e3) after csvread skipped the header: 0-based samples 4999..19999) divided by the normal
// load. It ignores where contact actually is; on the long real-tool files it averages seconds of no
// contact. Throws std::invalid_argument with fewer than 20000 samples or a non-positive load.
double upstream_mu(std::span<const double> tangential_force_N, double normal_load_N);

}  // namespace nibrig::model::measure
