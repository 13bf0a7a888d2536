#include "playback/round_trip_run.hpp"

#include <spdlog/spdlog.h>

#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <thread>

namespace nibrig::playback {
namespace {

// Silence until armed; from the first block after that, `count` pulses `interval` frames apart.
// The block where it starts is published, in frames since the stream's first callback: the same
// count the capture keeps, so a pulse's frame is its place in the recording.
class ImpulseTrain final : public rt::BlockRenderer {
 public:
  ImpulseTrain(const std::vector<double>& pulse, std::size_t interval, std::size_t count)
      : pulse_(pulse), interval_(interval), count_(count) {}

  void arm() { armed_.store(true, std::memory_order_release); }
  // The frame of the first pulse, once the audio thread has started the train.
  std::optional<std::size_t> start() const {
    const std::size_t s = published_start_.load(std::memory_order_acquire);
    if (s == kNotStarted) return std::nullopt;
    return s;
  }

  void render(float* out, std::size_t frames) noexcept override {
    if (start_ == kNotStarted && armed_.load(std::memory_order_acquire)) {
      start_ = frame_;
      published_start_.store(start_, std::memory_order_release);
    }
    for (std::size_t i = 0; i < frames; ++i) {
      float value = 0.0f;
      const std::size_t f = frame_ + i;
      if (start_ != kNotStarted && f >= start_) {
        const std::size_t k = f - start_;
        const std::size_t offset = k % interval_;
        if (k / interval_ < count_ && offset < pulse_.size())
          value = static_cast<float>(pulse_[offset]);
      }
      out[i] = value;
    }
    frame_ += frames;
  }

 private:
  static constexpr std::size_t kNotStarted = std::numeric_limits<std::size_t>::max();
  const std::vector<double>& pulse_;
  const std::size_t interval_, count_;
  std::atomic<bool> armed_{false};
  std::atomic<std::size_t> published_start_{kNotStarted};
  std::size_t start_ = kNotStarted;  // audio thread only
  std::size_t frame_ = 0;            // audio thread only
};

void check_round_trip_settings(const RoundTripSettings& s) {
  if (!s.device.input_channel)
    throw std::invalid_argument("the round trip needs an input channel to find the impulses in");
  if (s.impulses < 1 || s.impulses > 100000)
    throw std::invalid_argument("impulses: expected 1 to 100000, got " +
                                std::to_string(s.impulses));
  if (!(s.interval_s > 0.0 && s.interval_s <= 10.0))
    throw std::invalid_argument("impulse interval: expected (0, 10] s, got " +
                                std::to_string(s.interval_s) + " s");
  if (!(s.threshold > 0.0 && s.threshold <= 1.0))
    throw std::invalid_argument("threshold: expected (0, 1], got " + std::to_string(s.threshold));
  if (!(s.level > 0.0 && s.level <= 1.0))
    throw std::invalid_argument("level: expected (0, 1] of full scale, got " +
                                std::to_string(s.level));
}

double round_trip_ms(double samples, unsigned rate) { return 1e3 * samples / rate; }

RoundTripResult measure_round_trip_once(const RoundTripSettings& settings, unsigned period,
                                        const std::vector<double>& pulse, std::stop_token stop) {
  OutputSettings device = settings.device;
  device.period_frames = period;
  const auto interval =
      static_cast<std::size_t>(std::lround(settings.interval_s * device.sample_rate));
  if (interval < 2 * pulse.size())
    throw std::invalid_argument("impulse interval: " + std::to_string(settings.interval_s) +
                                " s is under two pulses (" + std::to_string(2 * pulse.size()) +
                                " samples at " + std::to_string(device.sample_rate) + " Hz)");
  const auto count = static_cast<std::size_t>(settings.impulses);

  ImpulseTrain train(pulse, interval, count);
  AudioOutput output(train, device);
  RoundTripResult result;
  result.stream = output.stream_info();
  result.period_asked = period;
  if (result.stream.sample_rate != device.sample_rate)
    throw std::runtime_error("the stream opened at " + std::to_string(result.stream.sample_rate) +
                             " Hz, not the " + std::to_string(device.sample_rate) + " Hz asked");
  if (settings.on_open) settings.on_open(result.stream);
  std::this_thread::sleep_for(settings.lead_in);
  train.arm();
  spdlog::info("latency: {} impulses {:.0f} ms apart on {} '{}' output {} -> input {}, period {}",
               count, 1e3 * settings.interval_s, result.stream.api, result.stream.device,
               device.output_channel, *device.input_channel, result.stream.period_frames);

  std::vector<float> recorded;
  std::vector<float> block(8192);
  const auto deadline = std::chrono::steady_clock::now() + settings.timeout;
  for (;;) {
    const std::size_t n = output.read_captured(block.data(), block.size());
    recorded.insert(recorded.end(), block.begin(), block.begin() + n);
    const auto start = train.start();
    if (start && recorded.size() >= *start + count * interval) break;
    if (stop.stop_requested()) return result;
    if (output.status() == OutputStatus::lost)
      throw std::runtime_error("latency: the device was lost while recording (" +
                               output.last_problem() + ")");
    if (std::chrono::steady_clock::now() > deadline)
      throw std::runtime_error("latency: recorded " + std::to_string(recorded.size()) +
                               " samples, not all impulses, within " +
                               std::to_string(settings.timeout.count()) + " s");
    if (n == 0) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  const OutputStats stats = output.stats();
  // A dropped sample shifts every later one: the frames would no longer line up with the pulses.
  if (stats.capture_dropped > 0)
    throw std::runtime_error("latency: the capture ring dropped " +
                             std::to_string(stats.capture_dropped) +
                             " samples; the recording no longer lines up with what was played");
  result.xruns = stats.output_underflows + stats.input_overflows;

  std::vector<std::size_t> played_at(count);
  for (std::size_t i = 0; i < count; ++i) played_at[i] = *train.start() + i * interval;
  ImpulseSearch search;
  search.max_lag_samples = interval - pulse.size();
  search.threshold = settings.threshold;
  result.impulses = find_impulses(pulse, played_at, recorded, search);
  result.stats = summarise_round_trips(result.impulses);
  const unsigned rate = result.stream.sample_rate;
  result.mean_ms = round_trip_ms(result.stats.mean_samples, rate);
  result.stddev_ms = round_trip_ms(result.stats.stddev_samples, rate);
  result.min_ms = round_trip_ms(static_cast<double>(result.stats.min_samples), rate);
  result.worst_ms = round_trip_ms(static_cast<double>(result.stats.worst_samples), rate);
  return result;
}

}  // namespace

std::vector<RoundTripResult> measure_round_trips(const RoundTripSettings& settings,
                                                 const std::vector<unsigned>& periods,
                                                 const RoundTripProgress& progress,
                                                 std::stop_token stop) {
  check_round_trip_settings(settings);
  const std::vector<double> pulse = round_trip_pulse(settings.level);
  const std::vector<unsigned> asked =
      periods.empty() ? std::vector<unsigned>{settings.device.period_frames} : periods;
  std::vector<RoundTripResult> results;
  for (unsigned period : asked) {
    if (period == 0) throw std::invalid_argument("period: expected a positive number of frames");
    RoundTripResult r = measure_round_trip_once(settings, period, pulse, stop);
    if (stop.stop_requested()) break;
    results.push_back(std::move(r));
    if (progress) progress(results.size(), asked.size(), results.back());
  }
  return results;
}

}  // namespace nibrig::playback
