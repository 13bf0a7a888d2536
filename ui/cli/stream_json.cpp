#include "ui/cli/stream_json.hpp"

namespace nibrig::ui::cli {

nlohmann::json stream_json(const playback::StreamInfo& s) {
  return {{"api", s.api},
          {"device", s.device},
          {"input_device",
           s.input_device.empty() ? nlohmann::json(nullptr) : nlohmann::json(s.input_device)},
          {"sample_rate_hz", s.sample_rate},
          {"period_frames", s.period_frames},
          {"output_channels", s.output_channels},
          {"input_channels", s.input_channels},
          {"api_latency_frames", s.latency_frames}};
}

nlohmann::json engine_stats_json(const rt::EngineStats& e) {
  return {{"callbacks", e.callbacks},
          {"frames", e.frames},
          {"overruns", e.overruns},
          {"device_xruns", e.device_xruns},
          {"callback_median_at_most_s", e.callback_time_quantile(0.5)},
          {"callback_p99_at_most_s", e.callback_time_quantile(0.99)},
          {"callback_max_s", e.max_callback_s},
          {"callback_max_cpu_s", e.max_callback_cpu_s},
          {"peak_output", e.peak_output},
          {"limited_samples", e.limited_samples},
          {"non_finite_samples", e.non_finite_samples},
          {"samples_above_speed_range", e.samples_above_speed_range},
          {"refused_commands", e.refused_commands}};
}

nlohmann::json output_stats_json(const playback::OutputStats& d) {
  return {{"callbacks", d.callbacks},
          {"frames", d.frames},
          {"output_underflows", d.output_underflows},
          {"input_overflows", d.input_overflows},
          {"capture_dropped", d.capture_dropped},
          {"losses", d.losses},
          {"reconnects", d.reconnects}};
}

nlohmann::json round_trips_json(const std::vector<playback::RoundTripResult>& results) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& r : results) {
    const bool found = r.stats.found > 0;
    const auto or_null = [found](double v) {
      return found ? nlohmann::json(v) : nlohmann::json(nullptr);
    };
    out.push_back({{"stream", stream_json(r.stream)},
                   {"period_asked_frames", r.period_asked},
                   {"played", r.stats.played},
                   {"found", r.stats.found},
                   {"mean_ms", or_null(r.mean_ms)},
                   {"sd_ms", or_null(r.stddev_ms)},
                   {"min_ms", or_null(r.min_ms)},
                   {"worst_ms", or_null(r.worst_ms)},
                   {"mean_samples", or_null(r.stats.mean_samples)},
                   {"sd_samples", or_null(r.stats.stddev_samples)},
                   {"min_samples", or_null(static_cast<double>(r.stats.min_samples))},
                   {"worst_samples", or_null(static_cast<double>(r.stats.worst_samples))},
                   {"weakest_correlation", or_null(r.stats.weakest_correlation)},
                   {"xruns", r.xruns}});
  }
  return out;
}

}  // namespace nibrig::ui::cli
