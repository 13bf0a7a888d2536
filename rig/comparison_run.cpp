#include "rig/comparison_run.hpp"

#include <algorithm>
#include <chrono>

#include "rig/live_simulation.hpp"

namespace nibrig::rig {

namespace {

// Appends `more` to `all` (the same bins): the report keeps every row of a run.
void append_rows(WaterfallRows& all, const WaterfallRows& more) {
  if (more.rows() == 0) return;
  if (all.rows() == 0) {
    all.first_row = more.first_row;
    all.bins = more.bins;
  }
  all.measured_db.insert(all.measured_db.end(), more.measured_db.begin(), more.measured_db.end());
  all.simulated_db.insert(all.simulated_db.end(), more.simulated_db.begin(), more.simulated_db.end());
  all.times_s.insert(all.times_s.end(), more.times_s.begin(), more.times_s.end());
  all.speeds_m_s.insert(all.speeds_m_s.end(), more.speeds_m_s.begin(), more.speeds_m_s.end());
  all.rows_lost += more.rows_lost;
}

}  // namespace

ComparisonRun run_comparison(Rig& rig, const SpeedProfile& profile,
                             const model::design::ToolSound& simulated,
                             const model::measure::ThresholdCurve& threshold,
                             const ComparisonRunOptions& options) {
  const RigDescription& d = rig.description();
  LiveComparisonSettings settings = options.analysis;
  settings.acceleration_rate_hz = d.acceleration_rate_hz;
  settings.speed_rate_hz = d.frame_rate_hz;
  // The settings' segment is meant for 48 kHz (4096 samples: 85 ms, 11.7 Hz bins); a rig at
  // another rate (a replayed paper recording at 1 kHz) keeps about the same resolution in time and
  // frequency — the power of two nearest the same duration — rather than the same sample count
  // (4 s at 1 kHz, a row per second).
  if (d.acceleration_rate_hz != 48000.0) {
    const double wanted = static_cast<double>(settings.spectrogram.segment_length) *
                          d.acceleration_rate_hz / 48000.0;
    std::size_t length = 16;
    while (static_cast<double>(length) * 1.5 < wanted) length *= 2;
    const double overlap = static_cast<double>(settings.spectrogram.hop) /
                            static_cast<double>(settings.spectrogram.segment_length);
    settings.spectrogram.segment_length = length;
    settings.spectrogram.hop = std::max<std::size_t>(1, static_cast<std::size_t>(overlap * static_cast<double>(length)));
  }
  LiveComparison comparison(settings, threshold);
  LiveSimulation simulation(simulated, d.acceleration_rate_hz, d.frame_rate_hz, options.seed);

  ComparisonRun run;
  run.simulated = simulated.name;
  run.settings = settings;
  std::vector<float> measured, simulated_m_s2, speed;
  WaterfallRows taken;
  auto last_update = std::chrono::steady_clock::now();
  CaptureOptions capture = options.capture;
  capture.on_data = [&](const RigData& data) {
    if (options.on_data) options.on_data(data);
    measured.clear();
    simulated_m_s2.clear();
    speed.clear();
    for (float a : data.acceleration)
      measured.push_back(static_cast<float>(a * d.accelerometer_m_s2_per_unit));
    simulation.feed(data, simulated_m_s2);
    for (const SensorFrame& f : data.frames) speed.push_back(f.speed_m_s);
    comparison.push(measured, simulated_m_s2, speed);
    const auto now = std::chrono::steady_clock::now();
    if (now - last_update >= std::chrono::milliseconds(100)) {
      last_update = now;
      if (options.on_update) {
        options.on_update(comparison);
      } else {
        comparison.take_new_rows(taken);
        append_rows(run.rows, taken);
      }
    }
  };
  run.capture = capture_session(rig, profile, capture);
  comparison.flush();
  comparison.finish();
  if (options.on_update) {
    options.on_update(comparison);
  } else {
    comparison.take_new_rows(taken);
    append_rows(run.rows, taken);
  }
  run.table = comparison.table();
  return run;
}

}  // namespace nibrig::rig
