// The cancel flag of fits and bootstrap refits: a flag already set starts nothing, one set midway
// stops the refits not yet begun, and either way the call throws numeric::Cancelled instead of
// returning a result computed from part of the work.
#include <gtest/gtest.h>

#include <stop_token>

#include "model/space/bootstrap.hpp"
#include "model/space/fit.hpp"
#include "tests/model/space/study_fixture.hpp"

namespace nibrig::model::space {
namespace {

SpaceProblem small_study() {
  return testing::every_triplet_judged(testing::random_truth(2, 7, 5), 6, 3);
}

TEST(SpaceCancellation, AStopRequestedBeforehandStartsNoFit) {
  std::stop_source cancel;
  cancel.request_stop();
  FitOptions options;
  options.stop = cancel.get_token();
  std::size_t calls = 0;
  EXPECT_THROW(fit_space(small_study(), options, [&](std::size_t, std::size_t) { ++calls; }),
               numeric::Cancelled);
  EXPECT_EQ(calls, 0u);
}

TEST(SpaceCancellation, AStopRequestedMidwayStopsTheRemainingRefits) {
  const SpaceProblem problem = small_study();
  const FitResult fit = fit_space(problem);
  std::stop_source cancel;
  BootstrapOptions options;
  options.resamples = 200;
  options.threads = 2;
  options.stop = cancel.get_token();
  std::size_t reported = 0;
  EXPECT_THROW(bootstrap_space(problem, fit.coordinates, options,
                               [&](std::size_t done, std::size_t) {
                                 reported = done;
                                 if (done == 3) cancel.request_stop();
                               }),
               numeric::Cancelled);
  // Refits already running when the stop was requested still finish (one per thread), none after.
  EXPECT_GE(reported, 3u);
  EXPECT_LE(reported, 3u + options.threads);
}

TEST(SpaceCancellation, AWatchedTokenChangesNothing) {
  const SpaceProblem problem = small_study();
  std::stop_source cancel;
  FitOptions options;
  options.stop = cancel.get_token();
  const FitResult watched = fit_space(problem, options);
  const FitResult plain = fit_space(problem);
  EXPECT_EQ(watched.coordinates, plain.coordinates);  // same seeds, same arithmetic
}

}  // namespace
}  // namespace nibrig::model::space
