#include "model/mechanics/ring_down_uncertainty.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace nibrig::model::mechanics {
namespace {

// The trace the fit's model makes at p = (ln E, ln λ, release time), before the gain.
std::vector<double> released_trace(const modal::ModalModel& reference,
                                   const RingDownOptions& options,
                                   const io::AccelerationTrace& trace, const Eigen::Vector3d& p) {
  const double ratio = std::exp(p[0]) / options.reference_modulus;
  const modal::ModalModel model =
      rescale_modulus(reference, ratio, {options.mass_damping, std::exp(p[1])});
  return simulate_release(model, options.preload, trace.sample_rate_hz,
                          trace.acceleration_m_s2.size(), std::max(0.0, p[2]));
}

}  // namespace

RingDownLinearisation linearise_ring_down(const modal::ModalModel& reference,
                                          const RingDownOptions& options,
                                          const io::AccelerationTrace& trace, double youngs_modulus,
                                          double rayleigh_stiffness, double release_time,
                                          double gain) {
  const auto& measured = trace.acceleration_m_s2;
  const int parameters = options.fit_gain ? 4 : 3;
  const auto n = static_cast<Eigen::Index>(measured.size());
  const Eigen::Vector3d p{std::log(youngs_modulus), std::log(rayleigh_stiffness), release_time};
  // Central differences: 1e-4 in the logs is 0.01 %, well inside the fit's precision and far above
  // rounding; the release time moves by a twentieth of a sample, the fit's own step. A release at
  // the first sample is differenced forward only, as times before the trace do not exist.
  const double steps[3] = {1e-4, 1e-4, 0.05 / trace.sample_rate_hz};
  RingDownLinearisation out;
  out.jacobian.resize(n, parameters);
  for (int k = 0; k < 3; ++k) {
    Eigen::Vector3d up = p, down = p;
    up[k] += steps[k];
    down[k] -= steps[k];
    double span = 2 * steps[k];
    if (k == 2 && down[k] < 0) down[k] = p[k], span = steps[k];
    const auto a = released_trace(reference, options, trace, up);
    const auto b = released_trace(reference, options, trace, down);
    for (Eigen::Index i = 0; i < n; ++i)
      out.jacobian(i, k) =
          gain * (a[static_cast<std::size_t>(i)] - b[static_cast<std::size_t>(i)]) / span;
  }
  const auto at_fit = released_trace(reference, options, trace, p);
  out.residual.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    if (options.fit_gain) out.jacobian(i, 3) = at_fit[static_cast<std::size_t>(i)];
    out.residual[i] =
        measured[static_cast<std::size_t>(i)] - gain * at_fit[static_cast<std::size_t>(i)];
  }
  return out;
}

RingDownUncertainty ring_down_uncertainty(const modal::ModalModel& reference,
                                          const RingDownOptions& options,
                                          const io::AccelerationTrace& trace,
                                          const RingDownFit& fit) {
  const auto& measured = trace.acceleration_m_s2;
  const int parameters = options.fit_gain ? 4 : 3;
  const auto n = static_cast<Eigen::Index>(measured.size());
  if (n <= parameters)
    throw std::invalid_argument(
        "ring-down uncertainty: the trace has no more samples than parameters");
  if (!(fit.youngs_modulus > 0) || !(fit.rayleigh_stiffness > 0))
    throw std::invalid_argument(
        "ring-down uncertainty: the fit has no positive modulus and stiffness damping");

  const RingDownLinearisation lin =
      linearise_ring_down(reference, options, trace, fit.youngs_modulus, fit.rayleigh_stiffness,
                          fit.release_time, fit.gain);
  const Eigen::MatrixXd& jacobian = lin.jacobian;
  const Eigen::VectorXd& residual = lin.residual;
  const double variance = residual.squaredNorm() / static_cast<double>(n - parameters);
  double lagged = 0.0;
  for (Eigen::Index i = 1; i < n; ++i) lagged += residual[i] * residual[i - 1];
  const double rho = residual.squaredNorm() > 0 ? lagged / residual.squaredNorm() : 0.0;

  RingDownUncertainty u;
  u.residual_rms = std::sqrt(residual.squaredNorm() / static_cast<double>(n));
  u.residual_correlation = rho;
  // Only positive correlation widens: negative (alternating) residuals would narrow the bounds,
  // and a fit should not claim more than white noise gives it.
  u.variance_inflation = rho > 0 ? (1 + rho) / std::max(1e-6, 1 - rho) : 1.0;

  const Eigen::MatrixXd information = jacobian.transpose() * jacobian;
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(information);
  if (ldlt.info() != Eigen::Success || !ldlt.isPositive() ||
      ldlt.vectorD().minCoeff() <= 1e-12 * ldlt.vectorD().maxCoeff())
    throw std::invalid_argument(
        "ring-down uncertainty: the trace does not determine modulus, damping and release (too "
        "short, or no ring-down in it)");
  const Eigen::MatrixXd covariance = variance * u.variance_inflation *
                                     ldlt.solve(Eigen::MatrixXd::Identity(parameters, parameters));
  // Standard deviations of the logs are relative ones (the delta method), accurate while they are
  // small, as they are for any trace the fit accepts.
  u.youngs_modulus_sd = fit.youngs_modulus * std::sqrt(covariance(0, 0));
  u.rayleigh_stiffness_sd = fit.rayleigh_stiffness * std::sqrt(covariance(1, 1));
  u.release_time_sd = std::sqrt(covariance(2, 2));
  u.modulus_damping_correlation = covariance(0, 1) / std::sqrt(covariance(0, 0) * covariance(1, 1));
  return u;
}

}  // namespace nibrig::model::mechanics
