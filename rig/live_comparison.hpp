// The live comparison of a rig capture: the capture thread hands measured and simulated
// acceleration and the measured speed over a lock-free queue, an analysis thread of its own runs
// the two streaming spectrograms and the speed-binned comparison, and a UI takes the new waterfall
// rows and the per-bin table whenever it draws. Neither the capture thread nor the UI ever waits
// for the analysis: the capture thread only copies into a queue slot, and the UI and the analysis
// thread share nothing but a snapshot behind a mutex that the capture thread never touches.
#pragma once

#include <array>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "model/measure/spectrogram.hpp"
#include "model/measure/speed_binned_comparison.hpp"
#include "model/measure/threshold_curve.hpp"
#include "rt/spsc_queue.hpp"

namespace nibrig::rig {

// What crosses the queue: up to a capacity of each stream, with the counts actually held.
// Trivially copyable (SpscQueue copies slots), fixed size, so nothing is allocated per block.
struct ComparisonBlock {
  static constexpr std::size_t kAccelerationCapacity = 512;  // 10.7 ms at 48 kHz
  static constexpr std::size_t kSpeedCapacity = 32;          // 32 ms at 1 kHz
  std::uint32_t acceleration_count = 0;
  std::uint32_t speed_count = 0;
  std::array<float, kAccelerationCapacity> measured{};
  std::array<float, kAccelerationCapacity> simulated{};
  std::array<float, kSpeedCapacity> speed_m_s{};
};

struct LiveComparisonSettings {
  double acceleration_rate_hz = 48000.0;
  double speed_rate_hz = 1000.0;
  // 4096 samples at 48 kHz: 11.7 Hz bins, 42 of them in the catalog's 6-500 Hz band, and a row
  // every 21 ms for the waterfall.
  model::measure::SpectrogramSettings spectrogram{4096, 1024, model::measure::Window::hann, true};
  model::measure::SpeedBinnedComparisonSettings comparison{};
  // Blocks the queue holds: 1024 × 512 samples is 10.9 s of 48 kHz audio that the analysis may fall
  // behind by (a UI stall, a slow disk) before the capture loses any.
  std::size_t queue_blocks = 1024;
  // Waterfall rows kept for a UI that has not taken them. When half as many again are waiting, the
  // oldest are dropped down to this many and counted (dropping now and then, not a row at a time,
  // keeps a capture without a UI from moving the whole waterfall up each time). 0: no waterfall is
  // kept at all (a command line that only wants the table).
  std::size_t max_waterfall_rows = 2048;
  // How often the table is recomputed and published while blocks arrive.
  std::chrono::milliseconds publish_interval{100};
  // How long the analysis thread sleeps when the queue is empty (the producer never signals: a
  // condition variable's notify may take a lock).
  std::chrono::milliseconds idle_sleep{2};
  // Amplitudes below this many dB re 1 m/s² are written as this value (log of zero).
  float floor_db = -200.0f;
};

// Rows added since the UI last took them: for each, the dB (20·log10 of the peak amplitude re
// 1 m/s²) of both streams at every frequency, row-major, ready to upload as texture rows.
struct WaterfallRows {
  std::uint64_t first_row = 0;  // the stream index of rows[0]
  std::size_t bins = 0;
  std::vector<float> measured_db, simulated_db;  // rows() × bins
  std::vector<double> times_s;                   // each row's centre (compute_spectrogram's)
  std::vector<double> speeds_m_s;                // each row's mean measured speed
  std::uint64_t rows_lost = 0;                   // dropped before the UI took them
  std::size_t rows() const { return times_s.size(); }
};

// The per-bin table, as last published.
struct ComparisonTable {
  std::vector<double> frequencies_hz;
  std::vector<model::measure::SpeedBinResult> bins;
  model::measure::ComparisonSummary summary;
  std::uint64_t rows_analysed = 0;
  std::uint64_t rows_without_speed = 0;  // no speed sample arrived for them (in the waterfall only)
  std::uint64_t blocks_dropped = 0;      // the queue was full: that audio was never analysed
  std::uint64_t pushes_refused = 0;      // measured and simulated of different lengths
  bool finished = false;                 // finish() has analysed everything
  // Why the analysis stopped, when it failed (finish() rethrows it): a UI shows it instead of a
  // table that silently stopped changing.
  std::string failure;
};

class LiveComparison {
 public:
  // Makes the spectrograms' plans, the queue and every buffer, and starts the analysis thread.
  // Throws what StreamingSpectrogram and SpeedBinnedComparison throw for bad settings, and
  // std::invalid_argument for rates that are not positive or a zero queue.
  LiveComparison(const LiveComparisonSettings& settings, model::measure::ThresholdCurve threshold);
  // finish()es.
  ~LiveComparison();
  LiveComparison(const LiveComparison&) = delete;
  LiveComparison& operator=(const LiveComparison&) = delete;

  // --- The capture thread (one producer) -------------------------------------------------------
  // Measured and simulated acceleration in step (the same number of samples, m/s²) and any number
  // of new measured speed samples (m/s). Copies into the block being filled and hands full blocks
  // to the queue. Never allocates, locks, blocks or throws: false when measured and simulated
  // differ in length (nothing is taken) or a block was dropped because the queue was full.
  bool push(std::span<const float> measured, std::span<const float> simulated,
            std::span<const float> speed_m_s) noexcept;
  // Hands over the partly filled block (at the end of a capture).
  bool flush() noexcept;

  // --- A control thread ------------------------------------------------------------------------
  // After the producer's last push and flush: the analysis thread analyses what is queued (rows
  // whose speed never came are put in the waterfall only), publishes a final table and ends.
  // Rethrows what stopped the analysis thread, if anything did. Idempotent.
  void finish();

  // --- The UI ----------------------------------------------------------------------------------
  // A copy of the last table (a few hundred kB with 4096-sample segments).
  ComparisonTable table() const;
  // How many tables have been published: a UI drawing every frame copies the table only when this
  // has changed. Lock-free.
  std::uint64_t table_version() const noexcept { return version_.load(std::memory_order_acquire); }
  // Moves the rows added since the last call into `out` (replacing its content); empty when none.
  void take_new_rows(WaterfallRows& out);

  const std::vector<double>& frequencies_hz() const { return frequencies_; }
  const LiveComparisonSettings& settings() const { return settings_; }

 private:
  struct Analysis;  // everything only the analysis thread touches
  bool send_staging() noexcept;
  void run();
  void publish(bool finished);

  LiveComparisonSettings settings_;
  std::vector<double> frequencies_;
  rt::SpscQueue<ComparisonBlock> queue_;
  // Producer-owned.
  ComparisonBlock staging_{};
  std::atomic<std::uint64_t> blocks_dropped_{0};
  std::atomic<std::uint64_t> pushes_refused_{0};

  std::unique_ptr<Analysis> analysis_;

  // Shared by the analysis thread and the UI only.
  mutable std::mutex snapshot_mutex_;
  ComparisonTable table_;
  WaterfallRows rows_;

  std::atomic<std::uint64_t> version_{0};
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace nibrig::rig
