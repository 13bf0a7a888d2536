#include "model/design/print_discrepancy.hpp"

#include <Eigen/Cholesky>
#include <cmath>
#include <stdexcept>

#include "model/space/catalog_descriptors.hpp"

namespace nibrig::model::design {

namespace {

void check_covariance(const Eigen::MatrixXd& m, std::size_t n, const std::string& what) {
  const auto size = static_cast<Eigen::Index>(n);
  if (m.rows() != size || m.cols() != size)
    throw std::invalid_argument(what + " must be " + std::to_string(n) + " x " + std::to_string(n) +
                                " (one row per descriptor)");
  if (!m.allFinite() || !m.isApprox(m.transpose(), 1e-9) || (m.diagonal().array() < 0).any())
    throw std::invalid_argument(what +
                                " must be a finite symmetric matrix with a non-negative diagonal");
}

}  // namespace

PrintDiscrepancy::PrintDiscrepancy(DiscrepancyPrior prior, std::vector<PrintResidual> prints)
    : prior_(std::move(prior)), prints_(std::move(prints)) {
  const std::size_t p = prior_.names.size();
  check_covariance(prior_.model_error, p, "the model's descriptor error");
  check_covariance(prior_.measurement_noise, p, "the measurement's descriptor noise");
  if (!(prior_.fraction_length > 0 && prior_.tip_length_m > 0))
    throw std::invalid_argument("the discrepancy's correlation lengths must be positive");
  for (const auto& r : prints_)
    if (r.measured_minus_predicted.size() != static_cast<Eigen::Index>(p) ||
        !r.measured_minus_predicted.allFinite())
      throw std::invalid_argument("the print " + to_string(r.point) + " needs " +
                                  std::to_string(p) + " finite descriptor residuals");
  if (prints_.empty()) return;
  // Σ(s) = s·K ⊗ C + I ⊗ R over the prints' stacked residuals r.
  const auto n = static_cast<Eigen::Index>(prints_.size()), q = static_cast<Eigen::Index>(p);
  Eigen::MatrixXd kc = Eigen::MatrixXd::Zero(n * q, n * q),
                  noise = Eigen::MatrixXd::Zero(n * q, n * q);
  Eigen::VectorXd r(n * q);
  for (Eigen::Index i = 0; i < n; ++i) {
    r.segment(i * q, q) = prints_[static_cast<std::size_t>(i)].measured_minus_predicted;
    for (Eigen::Index j = 0; j < n; ++j)
      kc.block(i * q, j * q, q, q) = correlation(prints_[static_cast<std::size_t>(i)].point,
                                                 prints_[static_cast<std::size_t>(j)].point) *
                                     prior_.model_error;
    noise.block(i * q, i * q, q, q) = prior_.measurement_noise;
  }
  // A small ridge keeps two prints of one design with R = 0 solvable; it is far below any
  // descriptor's variance.
  const double ridge =
      1e-12 * (1.0 + kc.diagonal().cwiseAbs().maxCoeff() + noise.diagonal().cwiseAbs().maxCoeff());
  const auto sigma_of = [&](double scale) {
    Eigen::MatrixXd sigma = scale * kc + noise;
    sigma.diagonal().array() += ridge;
    return sigma;
  };
  const auto log_likelihood = [&](double log_scale) {
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(sigma_of(std::exp(log_scale)));
    return -0.5 * r.dot(ldlt.solve(r)) - 0.5 * ldlt.vectorD().array().abs().log().sum();
  };
  // The scale by maximum likelihood over [1, kLargestModelErrorScale], golden sections on its log.
  double lo = 0.0, hi = std::log(kLargestModelErrorScale);
  const double golden = (std::sqrt(5.0) - 1) / 2;
  double x1 = hi - golden * (hi - lo), x2 = lo + golden * (hi - lo);
  double f1 = log_likelihood(x1), f2 = log_likelihood(x2);
  while (hi - lo > 1e-4) {
    if (f1 > f2) {
      hi = x2, x2 = x1, f2 = f1, x1 = hi - golden * (hi - lo), f1 = log_likelihood(x1);
    } else {
      lo = x1, x1 = x2, f1 = f2, x2 = lo + golden * (hi - lo), f2 = log_likelihood(x2);
    }
  }
  const double best = 0.5 * (lo + hi);
  scale_ = log_likelihood(best) > log_likelihood(0.0) ? std::exp(best) : 1.0;
  solve_ = sigma_of(scale_).ldlt().solve(Eigen::MatrixXd::Identity(n * q, n * q));
  alpha_ = solve_ * r;
}

double PrintDiscrepancy::correlation(const DesignPoint& a, const DesignPoint& b) const {
  const double df =
      (a.fraction_of(prior_.second_material) - b.fraction_of(prior_.second_material)) /
      prior_.fraction_length;
  const double dt = (a.tip_diameter_m - b.tip_diameter_m) / prior_.tip_length_m;
  return std::exp(-0.5 * (df * df + dt * dt));
}

DescriptorCorrection PrintDiscrepancy::at(const DesignPoint& point) const {
  const auto q = static_cast<Eigen::Index>(prior_.names.size());
  const auto n = static_cast<Eigen::Index>(prints_.size());
  DescriptorCorrection out{Eigen::VectorXd::Zero(q), scale_ * prior_.model_error};
  if (n == 0) return out;
  Eigen::MatrixXd cross(q, n * q);  // s·k(x)ᵀ ⊗ C
  for (Eigen::Index i = 0; i < n; ++i)
    cross.block(0, i * q, q, q) = scale_ *
                                  correlation(point, prints_[static_cast<std::size_t>(i)].point) *
                                  prior_.model_error;
  out.mean = cross * alpha_;
  out.covariance -= cross * solve_ * cross.transpose();
  out.covariance = 0.5 * (out.covariance + out.covariance.transpose());
  return out;
}

Eigen::MatrixXd measurement_descriptor_noise(const io::Catalog& catalog,
                                             const std::vector<std::string>& names) {
  // The nail pairs were recorded without friction: their vibration descriptors are read with a
  // stand-in μ of 0, whose row is replaced below.
  io::Catalog twice;
  const std::string first = "_nail1", second = "_nail2";
  for (const auto& p : catalog.pairings)
    if (p.vibration && p.tool.size() > first.size() &&
        (p.tool.compare(p.tool.size() - first.size(), first.size(), first) == 0 ||
         p.tool.compare(p.tool.size() - second.size(), second.size(), second) == 0)) {
      twice.pairings.push_back(p);
      twice.pairings.back().friction = io::FrictionDescriptor{};
    }
  const space::DescriptorTable table =
      space::descriptors_of_catalog(twice, "the catalog", names.size());
  if (table.names != names)
    throw std::invalid_argument("the catalog's descriptors are not the ones asked for");
  const auto q = static_cast<Eigen::Index>(names.size());
  Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(q, q);
  int pairs = 0;
  for (std::size_t a = 0; a < table.rows.size(); ++a) {
    const std::string& row = table.rows[a];
    const auto slash = row.find('/');
    const std::string tool = row.substr(0, slash), surface = row.substr(slash + 1);
    if (tool.compare(tool.size() - first.size(), first.size(), first) != 0) continue;
    const std::string other = tool.substr(0, tool.size() - first.size()) + second + "/" + surface;
    for (std::size_t b = 0; b < table.rows.size(); ++b)
      if (table.rows[b] == other) {
        const Eigen::VectorXd d = (table.values.row(static_cast<Eigen::Index>(a)) -
                                   table.values.row(static_cast<Eigen::Index>(b)))
                                      .transpose();
        sum += d * d.transpose();
        ++pairs;
      }
  }
  if (pairs == 0)
    throw std::invalid_argument(
        "the catalog holds no print recorded twice ('<tool>_nail1' and '<tool>_nail2' on one "
        "surface, with vibration), so a measurement's own descriptor noise is unknown");
  // Each recording carries the noise once; their difference twice.
  Eigen::MatrixXd noise = sum / (2.0 * pairs);
  // μ: the mean variance of the printed tools' measured μ, from their 95 % intervals.
  double variance = 0.0;
  int measured = 0;
  for (const auto& p : catalog.pairings)
    if (p.friction && p.friction->mu_ci_high > p.friction->mu_ci_low) {
      const double sd = (p.friction->mu_ci_high - p.friction->mu_ci_low) / (2 * 1.959963984540054);
      variance += sd * sd;
      ++measured;
    }
  noise.row(0).setZero();
  noise.col(0).setZero();
  noise(0, 0) = measured ? variance / measured : 0.0;
  return noise;
}

}  // namespace nibrig::model::design
