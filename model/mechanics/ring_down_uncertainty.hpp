// How sure a ring-down fit (ring_down.hpp) is of its modulus and damping: the least-squares
// covariance σ²(JᵀJ)⁻¹ at the fit, with J the trace's sensitivity to (ln E, ln λ, release time,
// gain) and σ² the residuals' variance, widened when the residuals are correlated from sample to
// sample (a recording's hum, or a model that misses something) rather than the white noise the
// formula assumes.
#pragma once

#include <Eigen/Core>

#include "model/io/acceleration_trace.hpp"
#include "model/mechanics/ring_down.hpp"
#include "model/modal/modal_model.hpp"

namespace nibrig::model::mechanics {

struct RingDownUncertainty {
  double youngs_modulus_sd = 0.0;      // Pa, one standard deviation
  double rayleigh_stiffness_sd = 0.0;  // s
  double release_time_sd = 0.0;        // s
  double modulus_damping_correlation = 0.0;
  double residual_rms = 0.0;  // in the trace's units
  // The residuals' lag-one autocorrelation ρ and the variance factor (1 + ρ)/(1 − ρ) (≥ 1) applied
  // for it: the number of independent samples in an AR(1) series is n(1 − ρ)/(1 + ρ).
  double residual_correlation = 0.0;
  double variance_inflation = 1.0;
};

// The trace's first-order model about (E, λ, release time, gain): the residuals measured − fitted
// and their Jacobian in (ln E, ln λ, release time[, gain when options.fit_gain]).
struct RingDownLinearisation {
  Eigen::MatrixXd jacobian;
  Eigen::VectorXd residual;
};
RingDownLinearisation linearise_ring_down(const modal::ModalModel& reference,
                                          const RingDownOptions& options,
                                          const io::AccelerationTrace& trace, double youngs_modulus,
                                          double rayleigh_stiffness, double release_time,
                                          double gain);

// The uncertainty of `fit`, fitted by fit_ring_down(reference, options, trace). Throws
// std::invalid_argument when the trace has no more samples than parameters, or when the trace does
// not determine the parameters (JᵀJ singular: a trace that ends before the bar rings).
RingDownUncertainty ring_down_uncertainty(const modal::ModalModel& reference,
                                          const RingDownOptions& options,
                                          const io::AccelerationTrace& trace,
                                          const RingDownFit& fit);

}  // namespace nibrig::model::mechanics
