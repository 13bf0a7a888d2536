#include "model/space/triplet_block.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

namespace nibrig::model::space {
namespace {

// A block of triplets' terms against triplet_terms<L>, one at a time: the same formulas with the
// transcendentals taken over the block by libmvec (within 4 ulp each), so every term agrees to
// 1e-12 relative. Random separations from near ties to 12 units, some exact ties and a candidate
// on its reference (x = 0), counts of 0 to 3 on each side, and a size that is no whole number of
// vectors.
template <Link L>
void expect_block_matches_one_by_one(double alpha, double lapse, double spread, unsigned seed,
                                     std::size_t size = 203) {
  const TripletKernel k{L, alpha, lapse};
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> x(0.0, spread);
  std::uniform_int_distribution<int> count(0, 3);
  TripletBlock b;
  b.size = size;
  for (std::size_t i = 0; i < b.size; ++i) {
    b.xa[i] = x(generator), b.xb[i] = x(generator);
    if (i % 17 == 0) b.xb[i] = b.xa[i];  // a tie: P = ½ each
    // A candidate on its reference, except for the Student-t in 1-D (α = 0), whose kernel 1/|x| is
    // infinite there, one triplet at a time as in a block.
    if (i % 23 == 0 && !(L == Link::student_t && alpha == 0.0)) b.xa[i] = 0.0;
    b.count_a[i] = count(generator), b.count_b[i] = count(generator);
  }
  for (bool with_gradient : {true, false}) {
    block_terms<L>(k, b, with_gradient);
    for (std::size_t i = 0; i < b.size; ++i) {
      const TripletTerms want =
          triplet_terms<L>(k, b.xa[i], b.xb[i], b.count_a[i], b.count_b[i], with_gradient);
      const TripletTerms got = b.terms(i);
      const std::string where = "link " + std::to_string(static_cast<int>(L)) + ", lapse " +
                                std::to_string(lapse) + ", x_a " + std::to_string(b.xa[i]) +
                                ", x_b " + std::to_string(b.xb[i]) + ", counts " +
                                std::to_string(b.count_a[i]) + "/" + std::to_string(b.count_b[i]);
      const auto near = [](double e) { return 1e-12 * std::max(1.0, std::abs(e)); };
      EXPECT_NEAR(got.nll, want.nll, near(want.nll)) << where;
      EXPECT_NEAR(got.d_xa, want.d_xa, near(want.d_xa)) << where;
      EXPECT_NEAR(got.d_xb, want.d_xb, near(want.d_xb)) << where;
      EXPECT_NEAR(got.d_lapse, want.d_lapse, near(want.d_lapse)) << where;
    }
  }
}

TEST(TripletBlock, EveryLinkGivesTheTermsOfOneTripletAtATime) {
  // Lapses: none (the links' own logs), a fitted one (logs of the mixture), and one below
  // kLapseInLogs (mixed in logs, one triplet at a time). α = dims − 1 for 1, 2 and 3 dimensions.
  for (double lapse : {0.0, 0.07, 1e-250}) {
    expect_block_matches_one_by_one<Link::probit>(1.0, lapse, 4.0, 1);
    expect_block_matches_one_by_one<Link::probit>(1.0, lapse, 12.0, 2);  // tails to Φ(−12)
    expect_block_matches_one_by_one<Link::logistic>(1.0, lapse, 12.0, 3);
    for (double alpha : {0.0, 1.0, 2.0})
      expect_block_matches_one_by_one<Link::student_t>(alpha, lapse, 6.0, 4);
  }
}

TEST(TripletBlock, AProbitTripletBeyondTheNormalTailIsStillWorkedOut) {
  // One confidently wrong triplet 40 units apart (Φ(−40) ≈ 4e-350 underflows): the block takes the
  // continued fraction, as one triplet at a time does, and its likelihood stays finite.
  const TripletKernel k{Link::probit, 1.0, 0.0};
  TripletBlock b;
  b.size = 9;
  for (std::size_t i = 0; i < b.size; ++i)
    b.xa[i] = 0.1 * static_cast<double>(i), b.xb[i] = 1.0, b.count_a[i] = 1, b.count_b[i] = 1;
  b.xa[4] = 41.0, b.xb[4] = 1.0, b.count_b[4] = 0;  // a chosen although 40 units further
  block_terms<Link::probit>(k, b, true);
  for (std::size_t i = 0; i < b.size; ++i) {
    const TripletTerms want = triplet_terms<Link::probit>(k, b.xa[i], b.xb[i], b.count_a[i],
                                                          b.count_b[i], true);
    EXPECT_NEAR(b.terms(i).nll, want.nll, 1e-12 * std::abs(want.nll)) << i;
    EXPECT_NEAR(b.terms(i).d_xa, want.d_xa, 1e-12 * std::max(1.0, std::abs(want.d_xa))) << i;
  }
  // −log Φ(−40) by its asymptotic series, 40²/2 + log(40·√(2π)) − log(1 − 1/40² + 3/40⁴) = 804.6084
  // (the next term is 15/40⁶).
  EXPECT_NEAR(b.terms(4).nll, 804.6084, 1e-3);
}

}  // namespace
}  // namespace nibrig::model::space
