#include "rig/live_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "model/measure/streaming_spectrogram.hpp"

namespace nibrig::rig {

namespace measure = model::measure;

namespace {

const LiveComparisonSettings& checked(const LiveComparisonSettings& s) {
  if (!(s.speed_rate_hz > 0.0) || !std::isfinite(s.speed_rate_hz))
    throw std::invalid_argument("live comparison: the speed rate must be positive and finite");
  if (s.queue_blocks == 0)
    throw std::invalid_argument("live comparison: the queue needs room for at least one block");
  return s;
}

}  // namespace

// Everything here belongs to the analysis thread alone (and to the constructor before it starts).
struct LiveComparison::Analysis {
  Analysis(const LiveComparisonSettings& s, measure::ThresholdCurve threshold)
      : measured(s.acceleration_rate_hz, s.spectrogram),
        simulated(s.acceleration_rate_hz, s.spectrogram),
        comparison(measured.frequencies_hz(), s.comparison, std::move(threshold)),
        bins(measured.bins()),
        // Rows wait here for their speed. Room for several blocks' rows however short the hop, so
        // that a simulated row is always still held when its measured twin must be completed.
        pending_capacity(std::max<std::size_t>(
            256, 4 * (ComparisonBlock::kAccelerationCapacity / s.spectrogram.hop + 2))),
        pending_measured(pending_capacity * bins),
        pending_simulated(pending_capacity * bins),
        // A minute of speed at the speed rate: far more than any row's span or any lag between
        // the streams in one block.
        speeds(std::max<std::size_t>(4096, static_cast<std::size_t>(60.0 * s.speed_rate_hz))) {
    batch.bins = bins;
  }

  measure::StreamingSpectrogram measured, simulated;
  measure::SpeedBinnedComparison comparison;
  std::size_t bins;
  std::size_t pending_capacity;
  std::vector<double> pending_measured, pending_simulated;  // slot (row % capacity) × bins
  std::uint64_t completed = 0;                              // rows completed so far
  std::vector<double> speeds;                               // ring: sample i at i % size
  std::uint64_t speed_total = 0;
  WaterfallRows batch;  // rows completed since the last publication
  std::uint64_t rows_without_speed = 0;
  std::exception_ptr failure;
};

LiveComparison::LiveComparison(const LiveComparisonSettings& settings,
                               model::measure::ThresholdCurve threshold)
    : settings_(checked(settings)),
      queue_(settings.queue_blocks),
      analysis_(std::make_unique<Analysis>(settings_, std::move(threshold))) {
  frequencies_ = analysis_->measured.frequencies_hz();
  rows_.bins = analysis_->bins;
  table_.frequencies_hz = frequencies_;
  table_.bins = analysis_->comparison.results();
  table_.summary = analysis_->comparison.summary();
  thread_ = std::thread([this] { run(); });
}

LiveComparison::~LiveComparison() {
  try {
    finish();
  } catch (...) {
    // A destructor must not throw; finish() called explicitly reports the failure.
  }
}

// ---- Producer ----------------------------------------------------------------------------------

bool LiveComparison::send_staging() noexcept {
  if (staging_.acceleration_count == 0 && staging_.speed_count == 0) return true;
  const bool sent = queue_.try_push(staging_);
  if (!sent) blocks_dropped_.fetch_add(1, std::memory_order_relaxed);
  staging_.acceleration_count = 0;
  staging_.speed_count = 0;
  return sent;
}

bool LiveComparison::push(std::span<const float> measured, std::span<const float> simulated,
                          std::span<const float> speed_m_s) noexcept {
  if (measured.size() != simulated.size()) {
    pushes_refused_.fetch_add(1, std::memory_order_relaxed);
    return false;
  }
  bool all_sent = true;
  std::size_t a = 0, v = 0;
  // Each pass copies at least one sample: a staging part that fills up is sent and emptied.
  while (a < measured.size() || v < speed_m_s.size()) {
    const std::size_t n = std::min<std::size_t>(
        measured.size() - a, ComparisonBlock::kAccelerationCapacity - staging_.acceleration_count);
    std::copy_n(measured.data() + a, n, staging_.measured.data() + staging_.acceleration_count);
    std::copy_n(simulated.data() + a, n, staging_.simulated.data() + staging_.acceleration_count);
    staging_.acceleration_count += static_cast<std::uint32_t>(n);
    a += n;
    const std::size_t m = std::min<std::size_t>(
        speed_m_s.size() - v, ComparisonBlock::kSpeedCapacity - staging_.speed_count);
    std::copy_n(speed_m_s.data() + v, m, staging_.speed_m_s.data() + staging_.speed_count);
    staging_.speed_count += static_cast<std::uint32_t>(m);
    v += m;
    if (staging_.acceleration_count == ComparisonBlock::kAccelerationCapacity ||
        staging_.speed_count == ComparisonBlock::kSpeedCapacity)
      all_sent = send_staging() && all_sent;
  }
  return all_sent;
}

bool LiveComparison::flush() noexcept { return send_staging(); }

// ---- Control -----------------------------------------------------------------------------------

void LiveComparison::finish() {
  if (thread_.joinable()) {
    stop_.store(true, std::memory_order_release);
    thread_.join();
  }
  if (analysis_ && analysis_->failure) std::rethrow_exception(analysis_->failure);
}

// ---- UI ----------------------------------------------------------------------------------------

ComparisonTable LiveComparison::table() const {
  std::lock_guard lock(snapshot_mutex_);
  return table_;
}

void LiveComparison::take_new_rows(WaterfallRows& out) {
  std::lock_guard lock(snapshot_mutex_);
  const std::uint64_t next = rows_.first_row + rows_.rows();
  out = std::move(rows_);
  rows_ = WaterfallRows{};
  rows_.first_row = next;
  rows_.bins = out.bins;
}

// ---- Analysis thread ---------------------------------------------------------------------------

namespace {

void append_db(std::vector<float>& out, std::span<const double> amplitude, float floor_db) {
  for (double a : amplitude) {
    const float db = a > 0.0 ? static_cast<float>(20.0 * std::log10(a)) : floor_db;
    out.push_back(std::max(db, floor_db));
  }
}

// Drops the `n` oldest rows of `rows`.
void drop_oldest(WaterfallRows& rows, std::size_t n) {
  const auto values = static_cast<std::ptrdiff_t>(n * rows.bins);
  rows.measured_db.erase(rows.measured_db.begin(), rows.measured_db.begin() + values);
  rows.simulated_db.erase(rows.simulated_db.begin(), rows.simulated_db.begin() + values);
  rows.times_s.erase(rows.times_s.begin(), rows.times_s.begin() + static_cast<std::ptrdiff_t>(n));
  rows.speeds_m_s.erase(rows.speeds_m_s.begin(),
                        rows.speeds_m_s.begin() + static_cast<std::ptrdiff_t>(n));
  rows.first_row += n;
  rows.rows_lost += n;
}

// Drops the oldest rows down to `max` once half as many again are waiting.
void trim(WaterfallRows& rows, std::size_t max) {
  if (rows.rows() > max + max / 2) drop_oldest(rows, rows.rows() - max);
}

}  // namespace

void LiveComparison::run() {
  Analysis& an = *analysis_;
  const std::size_t length = settings_.spectrogram.segment_length;

  // Row r of both streams is complete: into the comparison (when its speed is known) and the
  // waterfall.
  const auto complete_row = [&](double speed) {
    const std::uint64_t r = an.completed;
    const std::size_t slot = static_cast<std::size_t>(r % an.pending_capacity) * an.bins;
    const std::span<const double> m(an.pending_measured.data() + slot, an.bins);
    const std::span<const double> s(an.pending_simulated.data() + slot, an.bins);
    if (std::isfinite(speed))
      an.comparison.add(speed, m, s);
    else
      ++an.rows_without_speed;
    ++an.completed;
    if (settings_.max_waterfall_rows == 0) {
      ++an.batch.first_row;  // nobody wants rows: the next one would be the first
      return;
    }
    append_db(an.batch.measured_db, m, settings_.floor_db);
    append_db(an.batch.simulated_db, s, settings_.floor_db);
    an.batch.times_s.push_back(an.measured.row_time_s(r));
    an.batch.speeds_m_s.push_back(speed);
    trim(an.batch, settings_.max_waterfall_rows);
  };

  // Completes the oldest waiting row if all its speed samples are in, or regardless when `now`
  // (the capture ended, or the row's slot is needed): then it takes the speed samples of its span
  // that did arrive, and goes without a speed if none did. False when it must wait.
  const auto complete_next = [&](bool now) {
    const auto range =
        measure::speed_samples_of_span(an.completed * settings_.spectrogram.hop, length,
                                       settings_.acceleration_rate_hz, settings_.speed_rate_hz);
    if (an.speed_total < range.end && !now) return false;
    const std::uint64_t oldest =
        an.speed_total > an.speeds.size() ? an.speed_total - an.speeds.size() : 0;
    const std::uint64_t begin = std::max(range.begin, oldest);
    const std::uint64_t end = std::min(range.end, an.speed_total);
    double speed = std::numeric_limits<double>::quiet_NaN();
    if (end > begin) {
      double sum = 0.0;
      for (std::uint64_t i = begin; i < end; ++i) sum += an.speeds[i % an.speeds.size()];
      speed = sum / static_cast<double>(end - begin);
    }
    complete_row(speed);
    return true;
  };

  // Completes rows in order while both spectra are in and complete_next lets them go.
  const auto complete_ready = [&](bool at_end) {
    const std::uint64_t ready = std::min(an.measured.rows(), an.simulated.rows());
    while (an.completed < ready && complete_next(at_end)) {
    }
  };

  const auto process = [&](const ComparisonBlock& block) {
    for (std::uint32_t i = 0; i < block.speed_count; ++i)
      an.speeds[an.speed_total++ % an.speeds.size()] = block.speed_m_s[i];
    const std::span<const float> m(block.measured.data(), block.acceleration_count);
    const std::span<const float> s(block.simulated.data(), block.acceleration_count);
    an.measured.push(m, [&](const measure::SpectrogramRow& row) {
      // A row that would overwrite one still waiting for its speed: the speed is not coming in
      // time (the producer stopped sending it), so the waiting one goes with what has come.
      while (row.index - an.completed >= an.pending_capacity) complete_next(true);
      const std::size_t slot = static_cast<std::size_t>(row.index % an.pending_capacity) * an.bins;
      std::copy(row.amplitude.begin(), row.amplitude.end(), an.pending_measured.begin() + slot);
    });
    an.simulated.push(s, [&](const measure::SpectrogramRow& row) {
      const std::size_t slot = static_cast<std::size_t>(row.index % an.pending_capacity) * an.bins;
      std::copy(row.amplitude.begin(), row.amplitude.end(), an.pending_simulated.begin() + slot);
    });
    complete_ready(false);
  };

  try {
    auto last_publish = std::chrono::steady_clock::now();
    const auto publish_if_due = [&] {
      const auto now = std::chrono::steady_clock::now();
      if (now - last_publish >= settings_.publish_interval) {
        publish(false);
        last_publish = now;
      }
    };
    for (;;) {
      // Read before draining: whatever was pushed before finish() is in the queue by now.
      const bool stopping = stop_.load(std::memory_order_acquire);
      bool any = false;
      while (auto block = queue_.try_pop()) {
        process(*block);
        any = true;
        publish_if_due();
      }
      if (stopping) {
        complete_ready(true);
        publish(true);
        return;
      }
      if (!any) std::this_thread::sleep_for(settings_.idle_sleep);
      publish_if_due();
    }
  } catch (const std::exception& error) {
    an.failure = std::current_exception();
    try {
      std::lock_guard lock(snapshot_mutex_);
      table_.failure = std::string("live comparison: the analysis stopped: ") + error.what();
    } catch (...) {
      // No memory even for the message: finish() still rethrows the failure itself.
    }
  } catch (...) {
    an.failure = std::current_exception();
  }
}

void LiveComparison::publish(bool finished) {
  Analysis& an = *analysis_;
  ComparisonTable table;
  table.frequencies_hz = frequencies_;
  table.bins = an.comparison.results();
  table.summary = measure::SpeedBinnedComparison::summarize(
      table.bins, an.comparison.rows_outside_speed_range());
  table.rows_analysed = an.completed;
  table.rows_without_speed = an.rows_without_speed;
  table.blocks_dropped = blocks_dropped_.load(std::memory_order_relaxed);
  table.pushes_refused = pushes_refused_.load(std::memory_order_relaxed);
  table.finished = finished;

  std::lock_guard lock(snapshot_mutex_);
  table_ = std::move(table);
  version_.fetch_add(1, std::memory_order_release);
  WaterfallRows& batch = an.batch;
  // Rows the batch itself dropped leave a gap: the UI's rows must stay contiguous, so the older
  // ones go too (only when the analysis fell a whole waterfall behind between publications).
  if (rows_.rows() > 0 && rows_.first_row + rows_.rows() != batch.first_row)
    drop_oldest(rows_, rows_.rows());
  if (rows_.rows() == 0) rows_.first_row = batch.first_row;
  rows_.rows_lost += batch.rows_lost;
  rows_.measured_db.insert(rows_.measured_db.end(), batch.measured_db.begin(),
                           batch.measured_db.end());
  rows_.simulated_db.insert(rows_.simulated_db.end(), batch.simulated_db.begin(),
                            batch.simulated_db.end());
  rows_.times_s.insert(rows_.times_s.end(), batch.times_s.begin(), batch.times_s.end());
  rows_.speeds_m_s.insert(rows_.speeds_m_s.end(), batch.speeds_m_s.begin(), batch.speeds_m_s.end());
  trim(rows_, settings_.max_waterfall_rows);
  // The batch restarts after the rows just handed over, keeping its buffers.
  batch.first_row += batch.rows();
  batch.rows_lost = 0;
  batch.measured_db.clear();
  batch.simulated_db.clear();
  batch.times_s.clear();
  batch.speeds_m_s.clear();
}

}  // namespace nibrig::rig
