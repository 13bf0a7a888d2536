#include "model/space/bootstrap.hpp"

#include <boost/math/distributions/chi_squared.hpp>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

#include "model/numeric/parallel_for.hpp"
#include "model/space/fit.hpp"
#include "model/space/procrustes.hpp"

namespace nibrig::model::space {
namespace {

// Every response as (triplet index, chose a?), in a fixed order.
struct Response {
  std::size_t triplet;
  bool chose_a;
};

std::vector<Response> all_responses(const std::vector<io::Triplet>& triplets) {
  std::vector<Response> r;
  for (std::size_t t = 0; t < triplets.size(); ++t) {
    for (int k = 0; k < triplets[t].count_a; ++k) r.push_back({t, true});
    for (int k = 0; k < triplets[t].count_b; ++k) r.push_back({t, false});
  }
  return r;
}

SpaceProblem resample(const SpaceProblem& problem, const std::vector<Response>& responses,
                      std::mt19937_64& generator) {
  std::vector<io::Triplet> counts = problem.triplets;
  for (auto& t : counts) t.count_a = t.count_b = 0;
  std::uniform_int_distribution<std::size_t> pick(0, responses.size() - 1);
  for (std::size_t k = 0; k < responses.size(); ++k) {
    const Response& r = responses[pick(generator)];
    ++(r.chose_a ? counts[r.triplet].count_a : counts[r.triplet].count_b);
  }
  SpaceProblem p = problem;
  p.triplets.clear();
  for (const auto& t : counts)
    if (t.count_a + t.count_b > 0) p.triplets.push_back(t);
  return p;
}

ConfidenceRegion summarise(const std::vector<Eigen::MatrixXd>& aligned, Eigen::Index stimulus,
                           const std::vector<double>& levels) {
  const Eigen::Index dims = aligned.front().rows();
  const double n = static_cast<double>(aligned.size());
  ConfidenceRegion region;
  region.mean = Eigen::VectorXd::Zero(dims);
  for (const auto& a : aligned) region.mean += a.col(stimulus);
  region.mean /= n;
  region.covariance = Eigen::MatrixXd::Zero(dims, dims);
  for (const auto& a : aligned) {
    const Eigen::VectorXd d = a.col(stimulus) - region.mean;
    region.covariance += d * d.transpose();
  }
  region.covariance /= n - 1.0;
  // A stimulus that barely moves gives a near-singular covariance; a floor far below any
  // perceptible distance keeps the Mahalanobis distance finite.
  const Eigen::MatrixXd regularised =
      region.covariance + Eigen::MatrixXd::Identity(dims, dims) *
                              std::max(1e-12, 1e-9 * region.covariance.trace());
  const Eigen::MatrixXd inverse = regularised.inverse();
  std::vector<double> distance;
  for (const auto& a : aligned) {
    const Eigen::VectorXd d = a.col(stimulus) - region.mean;
    distance.push_back(std::sqrt(std::max(0.0, d.dot(inverse * d))));
  }
  std::sort(distance.begin(), distance.end());
  for (double level : levels) {
    // The smallest radius that encloses at least this fraction of the refits.
    const auto k = static_cast<std::size_t>(std::ceil(level * n)) - 1;
    region.radius.push_back(distance[std::min(k, distance.size() - 1)]);
  }
  return region;
}

}  // namespace

PlaneEllipse plane_ellipse(const ConfidenceRegion& region, std::size_t level, Eigen::Index axis_x,
                           Eigen::Index axis_y) {
  if (region.covariance.rows() < 2)
    return {region.radius.at(level) * std::sqrt(region.covariance(axis_x, axis_x)), 0.0, 0.0};
  Eigen::Matrix2d c;
  c << region.covariance(axis_x, axis_x), region.covariance(axis_x, axis_y),
      region.covariance(axis_y, axis_x), region.covariance(axis_y, axis_y);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(c);
  const double r = region.radius.at(level);
  PlaneEllipse e;  // eigenvalues ascending: the second is the major axis
  e.semi_axis_1 = r * std::sqrt(std::max(0.0, eigen.eigenvalues()(1)));
  e.semi_axis_2 = r * std::sqrt(std::max(0.0, eigen.eigenvalues()(0)));
  e.angle_rad = std::atan2(eigen.eigenvectors()(1, 1), eigen.eigenvectors()(0, 1));
  return e;
}

BootstrapResult bootstrap_space(const SpaceProblem& problem, const Eigen::MatrixXd& reference,
                                const BootstrapOptions& options,
                                const numeric::Progress& progress) {
  validate(problem);
  if (options.resamples < 2) throw std::invalid_argument("the bootstrap needs at least 2 resamples");
  if (reference.rows() != static_cast<Eigen::Index>(problem.dims) ||
      reference.cols() != static_cast<Eigen::Index>(problem.stimuli))
    throw std::invalid_argument("the reference space must be " + std::to_string(problem.dims) +
                                " × " + std::to_string(problem.stimuli));
  for (double level : options.levels)
    if (!(level > 0.0 && level < 1.0))
      throw std::invalid_argument("a confidence level must lie in (0, 1), got " +
                                  std::to_string(level));
  const std::vector<Response> responses = all_responses(problem.triplets);
  if (responses.empty()) throw std::invalid_argument("the bootstrap needs responses to resample");

  BootstrapResult result;
  result.levels = options.levels;
  result.aligned.resize(static_cast<std::size_t>(options.resamples));
  result.refit_objectives.resize(result.aligned.size());
  numeric::ProgressCounter counter(progress, result.aligned.size());
  numeric::parallel_for(result.aligned.size(), options.threads, [&](std::size_t k) {
    if (options.stop.stop_requested()) return;
    std::mt19937_64 generator(options.seed + static_cast<unsigned>(k));
    const SpaceProblem resampled = resample(problem, responses, generator);
    FitOptions fit_options;
    fit_options.starts = options.starts;
    fit_options.threads = 1;
    fit_options.seed = options.seed + static_cast<unsigned>(k);
    fit_options.initial = reference;
    const FitResult fit = fit_space(resampled, fit_options);
    result.aligned[k] = procrustes_align(fit.coordinates, reference);
    result.refit_objectives[k] = fit.objective;
    counter.finished();
  });
  numeric::throw_if_cancelled(options.stop, "bootstrap refits");
  for (Eigen::Index s = 0; s < reference.cols(); ++s)
    result.regions.push_back(summarise(result.aligned, s, options.levels));
  return result;
}

double mean_per_axis_sd(const BootstrapResult& result) {
  if (result.regions.empty()) return 0.0;
  double sum = 0.0;
  for (const auto& r : result.regions)
    sum += std::sqrt(r.covariance.trace() / static_cast<double>(r.covariance.rows()));
  return sum / static_cast<double>(result.regions.size());
}

ConfidenceRegion gaussian_region(const Eigen::VectorXd& mean, const Eigen::MatrixXd& covariance,
                                 const std::vector<double>& levels) {
  ConfidenceRegion region{mean, covariance, {}};
  const boost::math::chi_squared chi2(static_cast<double>(covariance.rows()));
  for (double l : levels) region.radius.push_back(std::sqrt(boost::math::quantile(chi2, l)));
  return region;
}

}  // namespace nibrig::model::space
