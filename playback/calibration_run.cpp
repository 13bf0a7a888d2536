#include "playback/calibration_run.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <ctime>
#include <stdexcept>
#include <thread>
#include <vector>

#include "model/io/utc_time.hpp"
#include "rt/engine.hpp"

namespace nibrig::playback {
namespace {

// Plays a prepared buffer once from its first call, then silence.
class BufferPlayer final : public rt::BlockRenderer {
 public:
  explicit BufferPlayer(const std::vector<double>& signal) : signal_(signal) {}
  void render(float* out, std::size_t frames) noexcept override {
    std::size_t at = position_.load(std::memory_order_relaxed);
    for (std::size_t i = 0; i < frames; ++i, ++at)
      out[i] = at < signal_.size() ? static_cast<float>(signal_[at]) : 0.0f;
    position_.store(at, std::memory_order_release);
  }
  std::size_t played() const { return position_.load(std::memory_order_acquire); }

 private:
  const std::vector<double>& signal_;
  std::atomic<std::size_t> position_{0};
};

// The inverse filter's length in time at every rate: 64 ms keeps it flat to 0.7 dB over the band at
// 2 to 8 kHz (calibration_inverse_filter_test), and a minimum-phase filter's latency is not its length.
constexpr double kInverseFilterSeconds = 0.064;

}  // namespace

InverseFilterSettings design_for_device_rate(InverseFilterSettings design, double device_rate_hz) {
  rt::EngineSettings engine;
  engine.sample_rate_hz = device_rate_hz;
  const double internal = rt::internal_rate_for(engine);
  design.sample_rate_hz = internal;
  design.taps = static_cast<std::size_t>(std::lround(kInverseFilterSeconds * internal));
  return design;
}

ActuatorCalibration run_calibration(const CalibrationRunSettings& settings) {
  if (!settings.device.input_channel)
    throw std::invalid_argument("calibration needs the accelerometer's input channel");
  if (!(settings.accelerometer_m_s2_per_unit > 0))
    throw std::invalid_argument("the accelerometer's scale must be positive");
  SineSweepSettings sweep = settings.sweep;
  sweep.sample_rate_hz = settings.device.sample_rate;
  validate(sweep);
  const std::vector<double> signal = exponential_sine_sweep(sweep);
  const auto lead = static_cast<std::size_t>(
      std::lround(sweep.sample_rate_hz * std::chrono::duration<double>(settings.lead_in).count()));
  std::vector<double> played(lead, 0.0);
  played.insert(played.end(), signal.begin(), signal.end());

  OutputSettings device = settings.device;
  // Enough ring for the whole recording: the control thread here only drains it now and then.
  device.capture_capacity = std::max(device.capture_capacity, std::size_t{1} << 16);

  // One pass: play and record. Captured sample j arrived in the callback that rendered frame j:
  // both count from the stream's first callback, which is where the player starts.
  struct Attempt {
    ResponseEstimate estimate;
    std::uint64_t xruns = 0;  // the device's own, during this attempt: they explain a bad one
  };
  auto measure = [&]() {
    BufferPlayer player(played);
    AudioOutput output(player, device);
    spdlog::info("calibration: playing {} sweep(s) of {:.1f} s on '{}' channel {}, recording channel {}",
                 sweep.repetitions, sweep.duration_s, output.stream_info().device,
                 device.output_channel, *device.input_channel);
    std::vector<float> captured;
    std::vector<float> block(8192);
    const auto deadline = std::chrono::steady_clock::now() + settings.timeout;
    while (captured.size() < played.size()) {
      const std::size_t n = output.read_captured(block.data(), block.size());
      captured.insert(captured.end(), block.begin(), block.begin() + n);
      if (std::chrono::steady_clock::now() > deadline)
        throw std::runtime_error("calibration: recorded " + std::to_string(captured.size()) +
                                 " of " + std::to_string(played.size()) + " samples within " +
                                 std::to_string(settings.timeout.count()) + " s");
      if (output.status() == OutputStatus::lost)
        throw std::runtime_error("calibration: the device was lost while recording (" +
                                 output.last_problem() + ")");
      if (n == 0) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    std::vector<double> recorded(signal.size());
    for (std::size_t j = 0; j < recorded.size(); ++j)
      recorded[j] = settings.accelerometer_m_s2_per_unit * captured[lead + j];
    const OutputStats stats = output.stats();
    return Attempt{estimate_response(sweep, signal, recorded),
                   stats.output_underflows + stats.input_overflows};
  };
  // How far the repetitions agree over the band: a block lost or late in one of them (an xrun
  // that really hit the data) shows as a low SNR between them. Empty with a single repetition.
  const double band_low = settings.design.band_low_hz, band_high = settings.design.band_high_hz;
  auto band_snr_db = [&](const ResponseEstimate& e) {
    std::vector<double> in_band;
    for (std::size_t k = 0; k < e.snr_db.size(); ++k)
      if (e.response.frequencies_hz[k] >= band_low && e.response.frequencies_hz[k] <= band_high)
        in_band.push_back(e.snr_db[k]);
    if (in_band.empty()) return 1e9;
    std::sort(in_band.begin(), in_band.end());
    return in_band[in_band.size() / 2];
  };
  Attempt best = measure();
  for (int attempt = 2; attempt <= settings.attempts && band_snr_db(best.estimate) < settings.min_snr_db;
       ++attempt) {
    spdlog::warn("calibration: the sweeps agree to only {:.1f} dB (median over {:.0f}-{:.0f} Hz; "
                 "the device reported {} xrun(s) meanwhile); measuring again",
                 band_snr_db(best.estimate), band_low, band_high, best.xruns);
    Attempt again = measure();
    if (band_snr_db(again.estimate) > band_snr_db(best.estimate)) best = std::move(again);
  }
  if (band_snr_db(best.estimate) < settings.min_snr_db)
    spdlog::warn("calibration: the best of {} attempts agrees to {:.1f} dB only ({} xrun(s) "
                 "during it); check the flatness it reports",
                 settings.attempts, band_snr_db(best.estimate), best.xruns);
  const ResponseEstimate& estimate = best.estimate;

  ActuatorCalibration calibration;
  calibration.name = settings.name;
  calibration.created = model::io::now_utc_iso8601();
  calibration.sweep = sweep;
  calibration.delay_s = estimate.delay_s;
  calibration.response = estimate.response;
  calibration.design = design_for_device_rate(settings.design, sweep.sample_rate_hz);
  calibration.filter = design_inverse_filter(calibration.response, calibration.design);
  return calibration;
}

}  // namespace nibrig::playback
