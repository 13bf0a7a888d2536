#include "model/space/spectral_start.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "model/io/triplets.hpp"
#include "model/space/fit.hpp"
#include "model/space/procrustes.hpp"
#include "tests/model/space/study_fixture.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::space {
namespace {

double rms_radius(const Eigen::MatrixXd& q) {
  const Eigen::MatrixXd centred = q.colwise() - q.rowwise().mean();
  return std::sqrt(centred.colwise().squaredNorm().mean());
}

// The RMS distance between a space's shape and the truth's (both centred, the space scaled to the
// truth's RMS radius, then rotated or reflected onto it: procrustes_align), relative to that radius.
double relative_procrustes_error(const Eigen::MatrixXd& q, const Eigen::MatrixXd& truth) {
  const Eigen::MatrixXd centred = truth.colwise() - truth.rowwise().mean();
  const Eigen::MatrixXd aligned = procrustes_align(q * (rms_radius(truth) / rms_radius(q)), centred);
  return std::sqrt((aligned - centred).colwise().squaredNorm().mean() /
                   centred.colwise().squaredNorm().mean());
}

TEST(SpectralStart, ItsSpaceIsTheTruthsShapeAtTheAskedRadius) {
  // Every triplet of 12 stimuli judged 4 times by the paper's observer. The start is a guess made
  // from answer shares (a share is not a distance: it saturates), not a fit: its shape within 35 %
  // of the truth's radius. Measured 21 % in 1-D and 17 % in 2-D; another random space is 116 % and
  // 114 % from the same truth.
  for (Eigen::Index dims : {1, 2}) {
    const Eigen::MatrixXd truth = testing::random_truth(dims, 12, 7);
    const SpaceProblem p = testing::every_triplet_judged(truth, 4, 8);
    const Eigen::MatrixXd q = spectral_start(p, 2.0);
    ASSERT_EQ(q.rows(), dims);
    ASSERT_EQ(q.cols(), 12);
    EXPECT_NEAR(std::sqrt(q.colwise().squaredNorm().mean()), 2.0, 1e-12) << dims;
    EXPECT_NEAR(q.rowwise().mean().norm(), 0.0, 1e-12) << dims;
    EXPECT_LT(relative_procrustes_error(q, truth), 0.35) << dims;
  }
}

TEST(SpectralStart, NoStartWhereThereIsNothingToScale) {
  SpaceProblem p;
  p.dims = 2;
  p.stimuli = 5;  // no triplets
  EXPECT_EQ(spectral_start(p, 2.0).size(), 0);
  p.stimuli = kSpectralStartMaxStimuli + 1;  // the dense eigensolver's limit
  p.triplets.push_back({0, 1, 2, 1, 0, ""});
  EXPECT_EQ(spectral_start(p, 2.0).size(), 0);
}

TEST(SpectralStart, OneStartOnSalmonsAlienEggsReachesTheBestOptimumKnown) {
  // Salmon's 300 items in 1-D, the paper's probit. Random starts stop with items in the wrong order:
  // measured, the best of 16 random starts ranged from 4,645 to 5,260 nats between seeds, and a
  // single random start reached 4,645 to 6,509. The spectral start alone reaches 4,647.9.
  const io::TripletSet set =
      io::read_salmon_csv(nibrig::test::shared_data() / "salmon_alien_eggs" / "responses_train.csv");
  SpaceProblem p;
  p.dims = 1;
  p.stimuli = set.stimuli.size();
  p.triplets = set.triplets;
  FitOptions options;
  options.starts = 1;
  const FitResult fit = fit_space(p, options);
  EXPECT_LT(fit.objective, 4655.0);
  options.spectral_start = false;  // the same one start, at random: a worse optimum
  EXPECT_GT(fit_space(p, options).objective, fit.objective);
}

}  // namespace
}  // namespace nibrig::model::space
