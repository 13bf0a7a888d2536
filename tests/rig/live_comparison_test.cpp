// The live comparison's analysis thread against the offline computation of the same signals, and
// the capture thread's side of it: no allocation, no waiting, drops counted when the queue is full.
#include "rig/live_comparison.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <random>
#include <thread>
#include <vector>

#include "model/measure/spectrogram.hpp"
#include "model/measure/speed_binned_comparison.hpp"
#include "tests/support/allocation_counter.hpp"

namespace nibrig::rig {
namespace {

namespace measure = model::measure;

measure::ThresholdCurve threshold() {
  return measure::ThresholdCurve({10.0, 250.0, 1000.0}, {0.05, 0.005, 0.1}, "test curve");
}

// Six seconds of a capture: measured is two tones and noise, simulated a tone that follows the
// speed and other noise, the speed a sweep over the comparison's range at 1 kHz.
struct Capture {
  std::vector<float> measured, simulated, speed;
};
Capture make_capture(double seconds, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 0.1);
  Capture c;
  const auto n = static_cast<std::size_t>(seconds * 48000.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / 48000.0;
    c.measured.push_back(static_cast<float>(0.5 * std::sin(2 * M_PI * 120.0 * t) +
                                            0.2 * std::sin(2 * M_PI * 310.0 * t) + noise(rng)));
    c.simulated.push_back(static_cast<float>(
        (0.3 + t / seconds) * std::sin(2 * M_PI * (100.0 + 40.0 * t) * t) + noise(rng)));
  }
  for (std::size_t i = 0; i < static_cast<std::size_t>(seconds * 1000.0); ++i)
    c.speed.push_back(
        static_cast<float>(0.017 + 0.23 * static_cast<double>(i) / (seconds * 1000.0)));
  return c;
}

// Pushes the capture as a capture thread would: acceleration in audio periods of `period`
// samples, each with the speed samples that fell due during it.
void produce(LiveComparison& live, const Capture& c, std::size_t period) {
  std::size_t speed_sent = 0;
  for (std::size_t pos = 0; pos < c.measured.size(); pos += period) {
    const std::size_t n = std::min(period, c.measured.size() - pos);
    const std::size_t speed_due = std::min(c.speed.size(), (pos + n) / 48);
    live.push(std::span<const float>(c.measured).subspan(pos, n),
              std::span<const float>(c.simulated).subspan(pos, n),
              std::span<const float>(c.speed).subspan(speed_sent, speed_due - speed_sent));
    speed_sent = speed_due;
  }
  live.flush();
}

TEST(LiveComparison, GivesTheOfflineComparisonOfTheSameSignals) {
  const Capture c = make_capture(6.0, 1);
  LiveComparisonSettings settings;
  LiveComparison live(settings, threshold());
  produce(live, c, 256);
  live.finish();
  const ComparisonTable table = live.table();
  ASSERT_TRUE(table.finished);
  EXPECT_EQ(table.blocks_dropped, 0u);

  // Offline: whole-signal spectrograms, each row's mean speed over its span, the same binning.
  const std::vector<double> m(c.measured.begin(), c.measured.end());
  const std::vector<double> s(c.simulated.begin(), c.simulated.end());
  const std::vector<double> v(c.speed.begin(), c.speed.end());
  const auto sm = measure::compute_spectrogram(m, 48000.0, settings.spectrogram);
  const auto ss = measure::compute_spectrogram(s, 48000.0, settings.spectrogram);
  measure::SpeedBinnedComparison offline(sm.frequencies_hz, settings.comparison, threshold());
  std::vector<double> row_m(sm.frequencies_hz.size()), row_s(row_m.size());
  for (Eigen::Index r = 0; r < sm.amplitude.rows(); ++r) {
    const auto span =
        measure::speed_samples_of_span(static_cast<std::uint64_t>(r) * settings.spectrogram.hop,
                                       settings.spectrogram.segment_length, 48000.0, 1000.0);
    double sum = 0.0;
    for (auto i = span.begin; i < span.end; ++i) sum += v[i];
    for (std::size_t k = 0; k < row_m.size(); ++k) {
      row_m[k] = sm.amplitude(r, static_cast<Eigen::Index>(k));
      row_s[k] = ss.amplitude(r, static_cast<Eigen::Index>(k));
    }
    offline.add(sum / static_cast<double>(span.end - span.begin), row_m, row_s);
  }
  EXPECT_EQ(table.rows_analysed, static_cast<std::uint64_t>(sm.amplitude.rows()));
  EXPECT_EQ(table.rows_without_speed, 0u);
  const auto expected = offline.results();
  ASSERT_EQ(table.bins.size(), expected.size());
  std::size_t filled = 0;
  for (std::size_t b = 0; b < expected.size(); ++b) {
    SCOPED_TRACE("speed bin " + std::to_string(b));
    ASSERT_EQ(table.bins[b].rows, expected[b].rows) << "each row in the bin of the same speed";
    if (expected[b].rows == 0) continue;
    ++filled;
    // The same analysis of the same samples; 1e-9 leaves room for summation order only.
    EXPECT_NEAR(table.bins[b].lsd_db, expected[b].lsd_db, 1e-9);
    EXPECT_NEAR(table.bins[b].weighted_mean_log10_difference,
                expected[b].weighted_mean_log10_difference, 1e-12);
    EXPECT_NEAR(table.bins[b].mean_speed_m_s, expected[b].mean_speed_m_s, 1e-12);
    for (std::size_t k = 0; k < expected[b].measured_mean.size(); ++k)
      ASSERT_NEAR(table.bins[b].measured_mean[k], expected[b].measured_mean[k], 1e-9);
  }
  EXPECT_EQ(filled, 12u) << "the sweep crosses every bin of 17-250 mm/s";
  EXPECT_GT(table.summary.mean_lsd_db, 1.0) << "the two streams differ, and the distance says so";

  // The waterfall: every row, in dB, as float.
  WaterfallRows rows;
  live.take_new_rows(rows);
  ASSERT_EQ(rows.rows(), static_cast<std::size_t>(sm.amplitude.rows()));
  EXPECT_EQ(rows.first_row, 0u);
  EXPECT_EQ(rows.rows_lost, 0u);
  ASSERT_EQ(rows.bins, sm.frequencies_hz.size());
  double worst_db = 0.0;
  for (std::size_t r = 0; r < rows.rows(); ++r) {
    EXPECT_DOUBLE_EQ(rows.times_s[r], sm.times_s[r]);
    for (std::size_t k = 0; k < rows.bins; ++k) {
      const auto i = static_cast<Eigen::Index>(r), j = static_cast<Eigen::Index>(k);
      worst_db = std::max(
          {worst_db,
           std::abs(rows.measured_db[r * rows.bins + k] - 20.0 * std::log10(sm.amplitude(i, j))),
           std::abs(rows.simulated_db[r * rows.bins + k] - 20.0 * std::log10(ss.amplitude(i, j)))});
    }
  }
  // Float dB: 24-bit mantissa on values up to ~200 dB is ~1e-5 dB.
  EXPECT_LT(worst_db, 1e-4);
  live.take_new_rows(rows);
  EXPECT_EQ(rows.rows(), 0u) << "rows are handed over once";
}

TEST(LiveComparison, TheUiTakesContiguousRowsWhileTheCaptureRuns) {
  const Capture c = make_capture(4.0, 2);
  LiveComparisonSettings settings;
  settings.publish_interval = std::chrono::milliseconds(5);
  LiveComparison live(settings, threshold());
  std::atomic<bool> produced{false};
  std::thread producer([&] {
    // 0.1 s of capture every 10 ms (ten times real time), so that the UI takes rows on the way.
    for (std::size_t pos = 0; pos < c.measured.size(); pos += 4800) {
      const std::size_t n = std::min<std::size_t>(4800, c.measured.size() - pos);
      live.push(std::span<const float>(c.measured).subspan(pos, n),
                std::span<const float>(c.simulated).subspan(pos, n),
                std::span<const float>(c.speed).subspan(pos / 48, n / 48));
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    live.flush();
    produced = true;
  });
  std::uint64_t next = 0, version = live.table_version();
  std::size_t takes_with_rows = 0, new_versions = 0;
  WaterfallRows rows;
  const auto take = [&] {
    live.take_new_rows(rows);
    if (rows.rows() == 0) return;
    EXPECT_EQ(rows.first_row, next) << "no row skipped or repeated between takes";
    EXPECT_EQ(rows.measured_db.size(), rows.rows() * rows.bins);
    next = rows.first_row + rows.rows();
    ++takes_with_rows;
  };
  while (!produced) {
    take();
    if (live.table_version() != version) version = live.table_version(), ++new_versions;
    std::this_thread::sleep_for(std::chrono::milliseconds(15));
  }
  producer.join();
  live.finish();
  take();
  EXPECT_EQ(next, 1 + (c.measured.size() - 4096) / 1024) << "every row reached the UI";
  EXPECT_GE(takes_with_rows, 3u) << "rows arrived while the capture ran, not only at the end";
  EXPECT_GE(new_versions, 3u) << "the table's version tells the UI a new table is there";
  EXPECT_GT(live.table_version(), version) << "finish() publishes a last table";
}

TEST(LiveComparison, RowsWhoseSpeedNeverComesReachTheWaterfallButNotTheTable) {
  // A capture whose speed stream stops after one second: later rows wait for their speed until the
  // waiting room is full or the capture ends, then go to the waterfall without a speed.
  const Capture c = make_capture(8.0, 4);
  Capture cut = c;
  cut.speed.resize(1000);
  LiveComparison live(LiveComparisonSettings{}, threshold());
  produce(live, cut, 480);
  live.finish();
  const auto table = live.table();
  const std::uint64_t rows = 1 + (c.measured.size() - 4096) / 1024;
  EXPECT_EQ(table.rows_analysed, rows);
  // Rows that start before 1 s (r · 1024 < 48000: rows 0-46) have at least some of their speed
  // samples, the last ones only those up to sample 999 that came; from row 47 on none came.
  EXPECT_EQ(table.summary.rows, 47u);
  EXPECT_EQ(table.rows_without_speed, rows - 47);
  WaterfallRows w;
  live.take_new_rows(w);
  EXPECT_EQ(w.rows(), rows);
  EXPECT_TRUE(std::isnan(w.speeds_m_s.back())) << "a row without speed says so";
  EXPECT_FALSE(std::isnan(w.speeds_m_s.front()));
}

TEST(LiveComparison, AWaterfallNobodyTakesKeepsItsNewestRowsAndCountsTheRest) {
  const Capture c = make_capture(6.0, 5);
  const std::uint64_t rows = 1 + (c.measured.size() - 4096) / 1024;  // 278
  for (const std::size_t max : {std::size_t{100}, std::size_t{0}}) {
    SCOPED_TRACE("max_waterfall_rows " + std::to_string(max));
    LiveComparisonSettings settings;
    settings.max_waterfall_rows = max;
    settings.publish_interval = std::chrono::milliseconds(1);
    LiveComparison live(settings, threshold());
    produce(live, c, 256);
    live.finish();
    EXPECT_EQ(live.table().rows_analysed, rows) << "the table does not depend on the waterfall";
    WaterfallRows w;
    live.take_new_rows(w);
    if (max == 0) {
      EXPECT_EQ(w.rows(), 0u) << "no waterfall asked for, none kept";
      continue;
    }
    // Between max and 1.5 max rows are kept, the newest, contiguous up to the last row.
    EXPECT_GE(w.rows(), max);
    EXPECT_LE(w.rows(), max + max / 2);
    EXPECT_EQ(w.first_row + w.rows(), rows);
    EXPECT_EQ(w.rows_lost, w.first_row) << "every row not handed over is counted";
  }
}

TEST(LiveComparison, TheProducersPushNeverAllocatesEvenWhenTheQueueIsFull) {
  const Capture c = make_capture(2.0, 3);
  LiveComparisonSettings settings;
  settings.queue_blocks = 8;
  // The analysis thread sleeps long between looks at the queue, so that the producer overruns it.
  settings.idle_sleep = std::chrono::milliseconds(500);
  LiveComparison live(settings, threshold());
  std::this_thread::sleep_for(std::chrono::milliseconds(20));  // let it go to sleep
  const std::size_t before = nibrig::testing::allocations_on_this_thread();
  std::size_t refused = 0;
  for (std::size_t pos = 0; pos + 64 <= c.measured.size(); pos += 64) {
    if (!live.push(std::span<const float>(c.measured).subspan(pos, 64),
                   std::span<const float>(c.simulated).subspan(pos, 64),
                   std::span<const float>(c.speed).subspan(pos / 64 % 1000, 1)))
      ++refused;
  }
  if (!live.flush()) ++refused;
  EXPECT_FALSE(live.push(std::span<const float>(c.measured).first(10),
                         std::span<const float>(c.simulated).first(9), {}))
      << "streams out of step are refused, not misaligned";
  const std::size_t allocated = nibrig::testing::allocations_on_this_thread() - before;
  EXPECT_EQ(allocated, 0u) << "the capture thread's push must not allocate";
  live.finish();
  const auto table = live.table();
  // 96000 samples in 512-sample blocks are 188 blocks against a queue of 8: most are dropped, and
  // every drop is both reported to the producer and counted.
  EXPECT_GT(table.blocks_dropped, 100u);
  EXPECT_EQ(table.blocks_dropped, refused);
  EXPECT_EQ(table.pushes_refused, 1u);
}

}  // namespace
}  // namespace nibrig::rig
