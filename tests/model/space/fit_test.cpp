#include "model/space/fit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "model/space/procrustes.hpp"
#include "model/space/simulated_observer.hpp"
#include "model/space/trial_plan.hpp"

namespace nibrig::model::space {
namespace {

// Every triplet of `truth` judged `judgments` times by the simulated Thurstonian observer.
SpaceProblem simulated_study(const Eigen::MatrixXd& truth, int judgments, unsigned seed) {
  const SimulatedObserver observer(truth);
  std::mt19937_64 generator(seed);
  SpaceProblem p;
  p.dims = static_cast<std::size_t>(truth.rows());
  p.stimuli = static_cast<std::size_t>(truth.cols());
  const std::vector<Trial> trials = plan_all_triplets(p.stimuli, judgments, generator());
  p.triplets = merge_trials(trials, observer.answer(trials, generator));
  return p;
}

double rms_error(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return std::sqrt((a - b).colwise().squaredNorm().mean());
}

TEST(SpaceFit, RecoversAKnownTwoDimensionalSpace) {
  std::mt19937 generator(4);
  std::uniform_real_distribution<double> spread(-2.0, 2.0);  // ± 2 units: 75-95 % preferences
  Eigen::MatrixXd truth(2, 10);
  for (Eigen::Index i = 0; i < truth.size(); ++i) truth.data()[i] = spread(generator);
  const SpaceProblem study = simulated_study(truth, 20, 8);  // 360 triplets × 20 judgments
  FitOptions options;
  options.starts = 8;
  const FitResult fit = fit_space(study, options);
  const Eigen::MatrixXd aligned = procrustes_align(fit.coordinates, truth);
  const double extent =
      std::sqrt((truth.colwise() - truth.rowwise().mean()).colwise().squaredNorm().mean());
  // 7200 binomial judgments pin each coordinate to a few hundredths of a unit; 10 % of the
  // configuration's spread leaves room for that noise and fails for any systematic distortion.
  EXPECT_LT(rms_error(aligned, truth), 0.10 * extent);
  ASSERT_EQ(fit.start_objectives.size(), 8u);
  EXPECT_DOUBLE_EQ(fit.start_objectives.front(), fit.objective);
  EXPECT_NEAR(fit.coordinates.col(0).norm(), 0.0, 0.0);  // stimulus 0 pinned at the origin
  // Every iteration evaluates at least once, and a backtracking line search rarely more than
  // twice: a count outside that is counting something else.
  EXPECT_GE(fit.evaluations, fit.iterations);
  EXPECT_LE(fit.evaluations, 2 * fit.iterations + 2);
}

TEST(SpaceFit, CorrelationTermOrientsTheAxesAlongTheDescriptors) {
  // A 2-D truth whose axes are the descriptors: with λ > 0 the fit needs no rotation to match.
  std::mt19937 generator(12);
  std::uniform_real_distribution<double> spread(-2.0, 2.0);
  Eigen::MatrixXd truth(2, 9);
  for (Eigen::Index i = 0; i < truth.size(); ++i) truth.data()[i] = spread(generator);
  SpaceProblem study = simulated_study(truth, 20, 3);
  study.lambda = 5.0;
  study.descriptors = truth.transpose();
  FitOptions options;
  options.starts = 8;
  const FitResult fit = fit_space(study, options);
  for (Eigen::Index d = 0; d < 2; ++d) {
    const Eigen::VectorXd q =
        fit.coordinates.row(d).transpose().array() - fit.coordinates.row(d).mean();
    const Eigen::VectorXd x = truth.row(d).transpose().array() - truth.row(d).mean();
    // Axis d must follow descriptor d (up to sign): |r| near 1 for a space drawn from them.
    EXPECT_GT(std::abs(q.dot(x) / (q.norm() * x.norm())), 0.95) << "axis " << d;
  }
}

TEST(SpaceFit, ProcrustesUndoesARotationAndShift) {
  Eigen::MatrixXd a(2, 4);
  a << 0, 1, 0, 2, 0, 0, 1, 1;
  const double t = 0.7;
  Eigen::Matrix2d r;
  r << std::cos(t), -std::sin(t), std::sin(t), std::cos(t);
  const Eigen::MatrixXd b = (r * a).colwise() + Eigen::Vector2d(3, -1);
  EXPECT_LT((procrustes_align(a, b) - b).norm(), 1e-12);
}

}  // namespace
}  // namespace nibrig::model::space
