// Progress callbacks of the long space jobs (fit starts, bootstrap refits, folds of a dimension
// scan): one call per unit, done counts 1..total, and the same results whether anyone watches or
// not.
#include <gtest/gtest.h>

#include <mutex>
#include <set>
#include <thread>
#include <utility>
#include <vector>

#include "model/space/bootstrap.hpp"
#include "model/space/dimension_scan.hpp"
#include "model/space/fit.hpp"
#include "tests/model/space/study_fixture.hpp"

namespace nibrig::model::space {
namespace {

// Records every call; the mutex only guards the record, so a callback that the library called
// concurrently would still be caught by `overlapped`.
struct Recorder {
  std::mutex mutex;
  std::vector<std::pair<std::size_t, std::size_t>> calls;
  int inside = 0;
  bool overlapped = false;

  numeric::Progress callback() {
    return [this](std::size_t done, std::size_t total) {
      {
        std::lock_guard lock(mutex);
        overlapped = overlapped || inside > 0;
        ++inside;
      }
      std::this_thread::yield();  // widen the window in which a second concurrent call would land
      std::lock_guard lock(mutex);
      --inside;
      calls.emplace_back(done, total);
    };
  }

  // Every count 1..total seen exactly once, with the same total each time.
  void expect_each_unit_once(std::size_t total) const {
    ASSERT_EQ(calls.size(), total);
    std::set<std::size_t> seen;
    for (const auto& [done, t] : calls) {
      EXPECT_EQ(t, total);
      seen.insert(done);
    }
    EXPECT_EQ(seen.size(), total);
    EXPECT_EQ(*seen.begin(), 1u);
    EXPECT_EQ(*seen.rbegin(), total);
    // The library serialises the calls (numeric::ProgressCounter), so a face's bar needs no lock.
    EXPECT_FALSE(overlapped);
  }
};

SpaceProblem small_study() {
  return testing::every_triplet_judged(testing::random_truth(2, 7, 5), 6, 3);
}

TEST(SpaceProgress, FitReportsEachStartOnceFromItsWorkers) {
  const SpaceProblem study = small_study();
  FitOptions options;
  options.starts = 12;
  options.threads = 3;  // more than one worker: the calls come from several threads
  Recorder recorder;
  const FitResult watched = fit_space(study, options, recorder.callback());
  recorder.expect_each_unit_once(12);
  // Starts are seeded by index, never by thread or by callback: watching changes nothing, exactly.
  const FitResult unwatched = fit_space(study, options);
  EXPECT_EQ(watched.coordinates, unwatched.coordinates);
  EXPECT_EQ(watched.start_objectives, unwatched.start_objectives);
}

TEST(SpaceProgress, BootstrapReportsEachRefitOnce) {
  const SpaceProblem study = small_study();
  const FitResult reference = fit_space(study, {});
  BootstrapOptions options;
  options.resamples = 10;
  options.threads = 3;
  Recorder recorder;
  const BootstrapResult watched =
      bootstrap_space(study, reference.coordinates, options, recorder.callback());
  recorder.expect_each_unit_once(10);
  const BootstrapResult unwatched = bootstrap_space(study, reference.coordinates, options);
  EXPECT_EQ(watched.refit_objectives, unwatched.refit_objectives);  // the same refits, bit for bit
  ASSERT_EQ(watched.aligned.size(), unwatched.aligned.size());
  for (std::size_t k = 0; k < watched.aligned.size(); ++k)
    EXPECT_EQ(watched.aligned[k], unwatched.aligned[k]);
}

TEST(SpaceProgress, DimensionScanCountsFoldFitsAcrossAllItsPoints) {
  const SpaceProblem study = small_study();
  DimensionScanOptions options;
  options.dims = {1, 2};
  options.cross_validation.folds = 3;
  options.cross_validation.fit.starts = 2;
  options.cross_validation.fit.threads = 2;
  Recorder recorder;
  const std::vector<DimensionScanPoint> watched =
      scan_dimensions(study, nullptr, options, recorder.callback());
  // 2 dimensions × 1 λ × 3 folds; folds run one after another, so the counts come in order.
  recorder.expect_each_unit_once(6);
  for (std::size_t k = 0; k < recorder.calls.size(); ++k) EXPECT_EQ(recorder.calls[k].first, k + 1);
  const std::vector<DimensionScanPoint> unwatched = scan_dimensions(study, nullptr, options);
  ASSERT_EQ(watched.size(), unwatched.size());
  for (std::size_t k = 0; k < watched.size(); ++k) {
    EXPECT_EQ(watched[k].mean_error, unwatched[k].mean_error);
    EXPECT_EQ(watched[k].individual_agreement, unwatched[k].individual_agreement);
  }
}

}  // namespace
}  // namespace nibrig::model::space
