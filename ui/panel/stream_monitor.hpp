// What the devices view says about the stream that runs, in words read at a glance: the callback's
// load over the last seconds and the xruns of the last minute. The audio thread keeps only
// cumulative counts (relaxed atomics: rt/engine_stats.hpp, playback/audio_output.hpp); the UI
// thread samples them each frame and keeps a short history here, so that the audio thread gets no
// lock and no allocation for it.
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <optional>

#include "rt/engine_stats.hpp"

namespace nibrig::ui::panel {

// The callback's wall time over a recent window, as fractions of the period. Read from the
// engine's histogram (ten bins a decade): the mean takes each bin's geometric middle, within 12 %
// of the true time; the worst is the upper edge of the highest bin reached (at most 26 % above the
// true worst), capped by the longest callback ever measured.
struct StreamLoad {
  std::uint64_t blocks = 0;
  double window_s = 0.0;
  double mean = 0.0, worst = 0.0;  // fractions of the period
};

// Xruns within the window (the last minute, or since sampling began when that is shorter).
struct RecentXruns {
  std::uint64_t device = 0;  // underflows the audio back end reported
  std::uint64_t own = 0;     // blocks whose rendering took longer than the period (the engine's)
  double window_s = 0.0;
};

class StreamMonitor {
 public:
  static constexpr double kLoadWindowS = 5.0;   // recent enough to follow a change, and thousands of blocks
  static constexpr double kXrunWindowS = 60.0;  // "in the last minute"
  static constexpr double kSampleEveryS = 0.1;  // history kept at most this often: a few hundred entries

  // The counts now (`now_s` on any steady clock). Counts that go back (a stream opened afresh)
  // start the history again.
  void sample(double now_s, const rt::EngineStats& engine, std::uint64_t device_xruns);
  void reset();
  // nullopt before two samples or when no block ran in the window.
  std::optional<StreamLoad> load(double period_s) const;
  RecentXruns xruns() const;

 private:
  struct Counts {
    double t = 0.0;
    std::uint64_t device = 0, own = 0, callbacks = 0;
  };
  struct Histogram {
    double t = 0.0;
    std::array<std::uint64_t, rt::kCallbackTimeBins> bins{};
  };
  std::optional<Counts> counts_now_;
  std::optional<Histogram> histogram_now_;
  double longest_s_ = 0.0;
  // Oldest first; the first entry is the newest at or before the window's start, once the history
  // reaches that far.
  std::deque<Counts> counts_;
  std::deque<Histogram> histograms_;
};

}  // namespace nibrig::ui::panel
