#include "ui/panel/stream_monitor.hpp"

#include <algorithm>
#include <cmath>

namespace nibrig::ui::panel {

namespace {

// Drops the entries before the newest one at or before `start`: that one stays as the baseline.
template <typename Entry>
void monitor_keep_from(std::deque<Entry>& history, double start) {
  while (history.size() >= 2 && history[1].t <= start) history.pop_front();
}

// A time that stands for callback-time bin b: its geometric middle (within a factor 10^0.05 of any
// time in it); half the first edge for bin 0; the longest callback for the open-ended last bin.
double monitor_bin_middle(std::size_t b, double longest_s) {
  if (b == 0) return 0.5 * rt::callback_time_bin_edge(1);
  if (b + 1 >= rt::kCallbackTimeBins) return std::max(rt::callback_time_bin_edge(b), longest_s);
  return std::sqrt(rt::callback_time_bin_edge(b) * rt::callback_time_bin_edge(b + 1));
}

}  // namespace

void StreamMonitor::reset() {
  counts_now_.reset();
  histogram_now_.reset();
  longest_s_ = 0.0;
  counts_.clear();
  histograms_.clear();
}

void StreamMonitor::sample(double now_s, const rt::EngineStats& engine, std::uint64_t device_xruns) {
  const Counts c{now_s, device_xruns, engine.overruns, engine.callbacks};
  // Counts that went back belong to a stream opened afresh; a history older than the minute (the
  // view was not drawn meanwhile) cannot tell what happened within it.
  if (counts_now_ && (c.device < counts_now_->device || c.own < counts_now_->own ||
                      c.callbacks < counts_now_->callbacks || now_s - counts_now_->t > kXrunWindowS))
    reset();
  Histogram h;
  h.t = now_s;
  h.bins = engine.callback_time_histogram;
  counts_now_ = c;
  histogram_now_ = h;
  longest_s_ = engine.max_callback_s;
  if (counts_.empty() || now_s - counts_.back().t >= kSampleEveryS) counts_.push_back(c);
  if (histograms_.empty() || now_s - histograms_.back().t >= kSampleEveryS) histograms_.push_back(h);
  monitor_keep_from(counts_, now_s - kXrunWindowS);
  monitor_keep_from(histograms_, now_s - kLoadWindowS);
}

std::optional<StreamLoad> StreamMonitor::load(double period_s) const {
  if (!histogram_now_ || histograms_.empty() || !(period_s > 0.0)) return std::nullopt;
  const Histogram& base = histograms_.front();
  StreamLoad load;
  load.window_s = histogram_now_->t - base.t;
  double sum_s = 0.0, worst_s = 0.0;
  for (std::size_t b = 0; b < rt::kCallbackTimeBins; ++b) {
    const std::uint64_t n = histogram_now_->bins[b] - base.bins[b];
    if (n == 0) continue;
    load.blocks += n;
    sum_s += static_cast<double>(n) * monitor_bin_middle(b, longest_s_);
    worst_s = b + 1 < rt::kCallbackTimeBins ? rt::callback_time_bin_edge(b + 1) : longest_s_;
  }
  if (load.blocks == 0) return std::nullopt;
  // The longest callback ever bounds the window's worst too, and more tightly when it is lower.
  if (longest_s_ > 0.0) worst_s = std::min(worst_s, longest_s_);
  load.mean = sum_s / static_cast<double>(load.blocks) / period_s;
  load.worst = worst_s / period_s;
  return load;
}

RecentXruns StreamMonitor::xruns() const {
  if (!counts_now_ || counts_.empty()) return {};
  const Counts& base = counts_.front();
  return {counts_now_->device - base.device, counts_now_->own - base.own, counts_now_->t - base.t};
}

}  // namespace nibrig::ui::panel
