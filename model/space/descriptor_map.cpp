#include "model/space/descriptor_map.hpp"

#include <sstream>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "model/space/objective.hpp"

namespace nibrig::model::space {
namespace {

Eigen::VectorXd standardised_row(const DescriptorMap& map, const Eigen::VectorXd& x) {
  Eigen::VectorXd z(x.size() + 1);
  z(0) = 1.0;
  z.tail(x.size()) = (x - map.descriptor_mean).array() / map.descriptor_scale.array();
  return z;
}

// A draw from N(mean, covariance); a zero covariance gives the mean.
Eigen::VectorXd draw(const Placement& p, const Eigen::MatrixXd& factor,
                     std::normal_distribution<double>& normal, std::mt19937_64& generator) {
  Eigen::VectorXd u(p.mean.size());
  for (Eigen::Index i = 0; i < u.size(); ++i) u(i) = normal(generator);
  return p.mean + factor * u;
}

// A factor F with F·Fᵀ = covariance; semi-definite covariances (a judged stimulus: zero) are fine.
Eigen::MatrixXd square_root(const Eigen::MatrixXd& covariance) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(covariance);
  return eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).cwiseSqrt().asDiagonal();
}

}  // namespace

DescriptorMap fit_descriptor_map(const Eigen::MatrixXd& coordinates,
                                 const Eigen::MatrixXd& descriptors,
                                 const std::vector<std::string>& names) {
  const Eigen::Index n = coordinates.cols(), p = descriptors.cols(), dims = coordinates.rows();
  if (descriptors.rows() != n)
    throw std::invalid_argument("the descriptor table has " + std::to_string(descriptors.rows()) +
                                " rows for " + std::to_string(n) + " stimuli");
  if (static_cast<Eigen::Index>(names.size()) != p)
    throw std::invalid_argument(std::to_string(names.size()) + " descriptor names for " +
                                std::to_string(p) + " columns");
  if (p == 0) throw std::invalid_argument("a descriptor map needs at least one descriptor");
  if (n <= p + 1)
    throw std::invalid_argument("a descriptor map of " + std::to_string(p) +
                                " descriptors needs more than " + std::to_string(p + 1) +
                                " stimuli, got " + std::to_string(n));
  if (!coordinates.allFinite() || !descriptors.allFinite())
    throw std::invalid_argument("the descriptor map's inputs must be finite");
  DescriptorMap map;
  map.descriptor_names = names;
  map.samples = static_cast<std::size_t>(n);
  map.descriptor_mean = descriptors.colwise().mean().transpose();
  map.descriptor_scale.resize(p);
  for (Eigen::Index j = 0; j < p; ++j) {
    const double sd =
        std::sqrt((descriptors.col(j).array() - map.descriptor_mean(j)).square().sum() /
                  static_cast<double>(n - 1));
    if (!(sd > 0.0))
      throw std::invalid_argument("descriptor '" + names[static_cast<std::size_t>(j)] +
                                  "' is the same for every stimulus: it cannot place anything");
    map.descriptor_scale(j) = sd;
  }
  Eigen::MatrixXd z(n, p + 1);
  for (Eigen::Index i = 0; i < n; ++i)
    z.row(i) = standardised_row(map, descriptors.row(i).transpose()).transpose();
  const Eigen::MatrixXd normal_matrix = z.transpose() * z;
  map.design_inverse = normal_matrix.inverse();
  map.coefficients = (map.design_inverse * z.transpose() * coordinates.transpose()).transpose();
  const Eigen::MatrixXd residual = coordinates - map.coefficients * z.transpose();  // dims × n
  map.residual_covariance = residual * residual.transpose() / static_cast<double>(n - p - 1);
  for (Eigen::Index d = 0; d < dims; ++d) {
    const double total = (coordinates.row(d).array() - coordinates.row(d).mean()).square().sum();
    map.r_squared.push_back(total > 0 ? 1.0 - residual.row(d).squaredNorm() / total : 0.0);
  }
  return map;
}

Placement place_from_descriptors(const DescriptorMap& map, const Eigen::VectorXd& descriptors) {
  if (descriptors.size() != map.descriptor_mean.size())
    throw std::invalid_argument("expected " + std::to_string(map.descriptor_mean.size()) +
                                " descriptors, got " + std::to_string(descriptors.size()));
  for (Eigen::Index j = 0; j < descriptors.size(); ++j)
    if (!std::isfinite(descriptors(j)))
      throw std::invalid_argument(
          "descriptor '" + map.descriptor_names[static_cast<std::size_t>(j)] + "' is not finite");
  const Eigen::VectorXd z = standardised_row(map, descriptors);
  for (Eigen::Index j = 0; j < z.size(); ++j)
    if (!(std::abs(z(j)) <= kFarthestStandardisedDescriptor)) {
      std::ostringstream message;
      message << "descriptor '" << map.descriptor_names[static_cast<std::size_t>(j)] << "' is " << descriptors(j)
              << ": expected within " << kFarthestStandardisedDescriptor << " standard deviations of the judged "
              << "stimuli's (" << map.descriptor_mean(j) << " ± " << map.descriptor_scale(j) << ")";
      throw std::invalid_argument(message.str());
    }
  Placement p;
  p.mean = map.coefficients * z;
  p.covariance = map.residual_covariance * (1.0 + z.dot(map.design_inverse * z));
  return p;
}

Placement place_from_descriptors(const DescriptorMap& map, const Eigen::VectorXd& descriptors,
                                 const Eigen::MatrixXd& descriptor_covariance) {
  Placement p = place_from_descriptors(map, descriptors);
  const Eigen::Index n = descriptors.size();
  if (descriptor_covariance.rows() != n || descriptor_covariance.cols() != n)
    throw std::invalid_argument("expected a " + std::to_string(n) + " x " + std::to_string(n) +
                                " descriptor covariance, got " +
                                std::to_string(descriptor_covariance.rows()) + " x " +
                                std::to_string(descriptor_covariance.cols()));
  for (Eigen::Index j = 0; j < n; ++j)
    if (!(std::isfinite(descriptor_covariance(j, j)) && descriptor_covariance(j, j) >= 0))
      throw std::invalid_argument("the variance of descriptor '" +
                                  map.descriptor_names[static_cast<std::size_t>(j)] +
                                  "' is negative or not finite");
  const double asymmetry = (descriptor_covariance - descriptor_covariance.transpose()).norm();
  if (!(asymmetry <= 1e-12 * (1.0 + descriptor_covariance.norm())))
    throw std::invalid_argument("the descriptor covariance is not symmetric");
  const Eigen::MatrixXd jacobian =
      map.coefficients.rightCols(n) * map.descriptor_scale.cwiseInverse().asDiagonal();
  p.covariance += jacobian * descriptor_covariance * jacobian.transpose();
  return p;
}

UncertainProbability uncertain_probability_first(const Placement& reference, const Placement& a,
                                                 const Placement& b, const JudgmentModel& model, int samples,
                                                 std::mt19937_64& generator) {
  if (samples < 2) throw std::invalid_argument("an uncertain probability needs at least 2 samples");
  const Eigen::MatrixXd lr = square_root(reference.covariance), la = square_root(a.covariance),
                        lb = square_root(b.covariance);
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::MatrixXd q(reference.mean.size(), 3);
  double sum = 0.0, sum_sq = 0.0;
  for (int k = 0; k < samples; ++k) {
    q.col(0) = draw(reference, lr, normal, generator);
    q.col(1) = draw(a, la, normal, generator);
    q.col(2) = draw(b, lb, normal, generator);
    const double p = probability_first(model, static_cast<std::size_t>(q.rows()), (q.col(1) - q.col(0)).norm(),
                                       (q.col(2) - q.col(0)).norm(), typical_log_sigma(model));
    sum += p;
    sum_sq += p * p;
  }
  UncertainProbability u;
  u.mean = sum / samples;
  u.sd = std::sqrt(std::max(0.0, (sum_sq - sum * sum / samples) / (samples - 1)));
  return u;
}

UncertainDistance uncertain_distance(const Placement& a, const Placement& b, int samples,
                                     std::mt19937_64& generator) {
  if (a.mean.size() != b.mean.size())
    throw std::invalid_argument("uncertain_distance: placements of different dimensions");
  if (samples < 2) throw std::invalid_argument("an uncertain distance needs at least 2 samples");
  const Eigen::MatrixXd la = square_root(a.covariance), lb = square_root(b.covariance);
  std::normal_distribution<double> normal;
  double sum = 0, sum_sq = 0;
  for (int k = 0; k < samples; ++k) {
    const double d = (draw(a, la, normal, generator) - draw(b, lb, normal, generator)).norm();
    sum += d;
    sum_sq += d * d;
  }
  UncertainDistance u;
  u.between_means = (a.mean - b.mean).norm();
  u.sd = std::sqrt(std::max(0.0, (sum_sq - sum * sum / samples) / (samples - 1)));
  return u;
}

GroupDistance uncertain_group_distance(const Placement& a, const std::vector<Placement>& targets, GroupAim aim,
                                       int samples, std::mt19937_64& generator) {
  if (targets.empty()) throw std::invalid_argument("uncertain_group_distance: no targets");
  for (const auto& t : targets)
    if (t.mean.size() != a.mean.size())
      throw std::invalid_argument("uncertain_group_distance: placements of different dimensions");
  if (samples < 2) throw std::invalid_argument("an uncertain distance needs at least 2 samples");
  const auto aggregate = [aim](const std::vector<double>& d) {
    double out = aim == GroupAim::largest ? d.front() : 0.0;
    for (double x : d) out = aim == GroupAim::largest ? std::max(out, x) : out + x / static_cast<double>(d.size());
    return out;
  };
  const std::size_t n = targets.size();
  const Eigen::MatrixXd la = square_root(a.covariance);
  std::vector<Eigen::MatrixXd> lt;
  for (const auto& t : targets) lt.push_back(square_root(t.covariance));
  std::normal_distribution<double> normal;
  std::vector<double> sum(n + 1, 0.0), sum_sq(n + 1, 0.0), d(n);
  for (int k = 0; k < samples; ++k) {
    const Eigen::VectorXd xa = draw(a, la, normal, generator);
    for (std::size_t i = 0; i < n; ++i) d[i] = (xa - draw(targets[i], lt[i], normal, generator)).norm();
    const double g = aggregate(d);
    for (std::size_t i = 0; i <= n; ++i) {
      const double v = i < n ? d[i] : g;
      sum[i] += v;
      sum_sq[i] += v * v;
    }
  }
  const auto sd = [&](std::size_t i) {
    return std::sqrt(std::max(0.0, (sum_sq[i] - sum[i] * sum[i] / samples) / (samples - 1)));
  };
  GroupDistance out;
  std::vector<double> between(n);
  for (std::size_t i = 0; i < n; ++i) {
    between[i] = (a.mean - targets[i].mean).norm();
    out.each.push_back({between[i], sd(i)});
  }
  out.aggregate = {aggregate(between), sd(n)};
  return out;
}

}  // namespace nibrig::model::space
