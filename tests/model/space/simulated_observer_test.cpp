#include "model/space/simulated_observer.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace nibrig::model::space {
namespace {

TEST(SimulatedObserver, RandomSpaceHasTheRequestedDistanceDifferences) {
  for (std::size_t dims : {1u, 2u, 5u}) {
    std::mt19937_64 generator(dims);
    const Eigen::MatrixXd q = random_space(dims, 15, generator);
    EXPECT_EQ(q.rows(), static_cast<Eigen::Index>(dims));
    EXPECT_EQ(q.cols(), 15);
    // The scale is set by construction: only round-off separates it from the target.
    EXPECT_NEAR(rms_distance_difference(q), kDefaultTruthDifference, 1e-12);
    EXPECT_NEAR(rms_distance_difference(random_space(dims, 15, generator, 0.5)), 0.5, 1e-12);
  }
  std::mt19937_64 generator(1);
  EXPECT_THROW(random_space(0, 15, generator), std::invalid_argument);
  EXPECT_THROW(random_space(2, 2, generator), std::invalid_argument);
  EXPECT_THROW(random_space(2, 15, generator, 0.0), std::invalid_argument);
}

TEST(SimulatedObserver, AnswerFrequencyMatchesTheModelProbability) {
  Eigen::MatrixXd q(1, 5);
  q << 0.0, 0.4, 1.0, 2.5, -4.0;  // differences from 0 to 3.6 units: p from 0.5 to 0.92
  const SimulatedObserver observer(q);
  std::mt19937_64 generator(17);
  const int n = 20000;
  for (const auto& [r, a, b] : {std::array<std::size_t, 3>{0, 1, 2},
                                {0, 2, 3},
                                {0, 4, 3},
                                {1, 0, 2},
                                {2, 1, 3},
                                {0, 1, 4}}) {
    const double p = probability_first(JudgmentModel{}, q, r, a, b);
    EXPECT_DOUBLE_EQ(observer.probability_first(r, a, b), p);
    std::vector<Trial> trials(static_cast<std::size_t>(n), Trial{r, a, b, 1});
    int first = 0;
    for (Choice c : observer.answer(trials, generator)) first += c == Choice::left;
    // 4.5 binomial standard deviations: 1 failure in ~150 000 runs per triplet if correct, while
    // an observer off by 2 % in probability fails at this n.
    EXPECT_NEAR(static_cast<double>(first) / n, p, 4.5 * std::sqrt(p * (1 - p) / n))
        << "triplet " << r << "; " << a << ", " << b;
  }
  // The side shown does not matter to the observer: right chosen with 1 − p.
  std::vector<Trial> swapped(static_cast<std::size_t>(n), Trial{0, 2, 1, 1});
  int right = 0;
  for (Choice c : observer.answer(swapped, generator)) right += c == Choice::right;
  const double p = probability_first(JudgmentModel{}, q, 0, 1, 2);
  EXPECT_NEAR(static_cast<double>(right) / n, p, 4.5 * std::sqrt(p * (1 - p) / n));
}

TEST(SimulatedObserver, RejectsWhatItCannotAnswer) {
  EXPECT_THROW(SimulatedObserver(Eigen::MatrixXd::Zero(2, 2)), std::invalid_argument);
  const SimulatedObserver observer(Eigen::MatrixXd::Zero(2, 4));
  std::mt19937_64 generator(1);
  EXPECT_THROW(observer.answer({Trial{0, 1, 9, 1}}, generator), std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::model::space

namespace nibrig::model::space {
namespace {

TEST(SimulatedObserver, ASpaceFromDescriptorsKeepsTheirStandardisedShape) {
  Eigen::MatrixXd d(4, 2);
  d << 0.1, 10, 0.2, 30, 0.3, 20, 0.4, 40;
  const Eigen::MatrixXd q = space_from_descriptors(d, 1.5);
  EXPECT_NEAR(rms_distance_difference(q), 1.5, 1e-12);
  // Axis 1 is descriptor 1 up to a positive affine map: equal steps stay equal.
  EXPECT_NEAR(q(0, 1) - q(0, 0), q(0, 3) - q(0, 2), 1e-12);
  // Both axes are standardised before the common scale: their spreads are equal.
  const auto spread = [&](Eigen::Index r) { return (q.row(r).array() - q.row(r).mean()).matrix().norm(); };
  EXPECT_NEAR(spread(0), spread(1), 1e-12);
  d.col(1).setConstant(2.0);
  EXPECT_THROW(space_from_descriptors(d), std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::model::space
