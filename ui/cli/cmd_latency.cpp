// `nibrig latency`: the whole chain's round trip (output, actuator or loopback cable, input),
// measured with impulses found in the input, for one or several periods, printed as a table.
#include <spdlog/spdlog.h>

#include <cstdio>

#include "playback/audio_devices.hpp"
#include "playback/device_error.hpp"
#include "playback/round_trip_run.hpp"
#include "ui/cli/commands.hpp"
#include "ui/cli/device_options.hpp"
#include "ui/cli/logging.hpp"
#include "ui/cli/output.hpp"
#include "ui/cli/stream_json.hpp"
#include "ui/options/number_checks.hpp"

namespace nibrig::ui::cli {
namespace {

struct LatencyOptions {
  DeviceOptions device;
  std::string input_device;
  unsigned input_channel = 1;
  std::vector<unsigned> periods{64};
  int impulses = 50;
  double interval_ms = 250.0;
  double level = 0.25;
  double threshold = 0.5;
  std::filesystem::path json;
};

void print_latency_table(const std::vector<playback::RoundTripResult>& results) {
  // "api says": the stream latency the back end reports (RtAudio's), beside what was measured.
  std::printf("%-6s %-16s %-16s %6s %6s %7s %8s %8s %8s %9s %8s %9s %8s\n", "api", "output",
              "input", "rate", "period", "found", "mean ms", "sd ms", "worst ms", "mean smp",
              "sd smp", "worst smp", "api says");
  for (const auto& r : results) {
    const std::string& input =
        r.stream.input_device.empty() ? r.stream.device : r.stream.input_device;
    std::printf("%-6s %-16s %-16s %6u %6u %3zu/%-3zu ", r.stream.api.c_str(),
                r.stream.device.c_str(), input.c_str(), r.stream.sample_rate,
                r.stream.period_frames, r.stats.found, r.stats.played);
    // With nothing found there is no round trip to show, and a 0 would read as one.
    if (r.stats.found > 0) {
      std::printf("%8.3f %8.3f %8.3f %9.1f %8.1f %9zu", r.mean_ms, r.stddev_ms, r.worst_ms,
                  r.stats.mean_samples, r.stats.stddev_samples, r.stats.worst_samples);
    } else {
      std::printf("%8s %8s %8s %9s %8s %9s", "-", "-", "-", "-", "-", "-");
    }
    std::printf(" %8ld\n", r.stream.latency_frames);
  }
  for (const auto& r : results) {
    const std::string row = "period " + std::to_string(r.period_asked);
    if (r.period_asked != r.stream.period_frames)
      std::printf("%s: %s ran %u-frame periods instead\n", row.c_str(), r.stream.api.c_str(),
                  r.stream.period_frames);
    if (r.stats.found < r.stats.played)
      std::printf(
          "%s: %zu impulse(s) not found (correlation under the threshold): counted, "
          "not averaged in\n",
          row.c_str(), r.stats.played - r.stats.found);
    if (r.xruns > 0)
      std::printf("%s: the device reported %llu xrun(s) while measuring\n", row.c_str(),
                  static_cast<unsigned long long>(r.xruns));
  }
}

void latency(const LatencyOptions& o) {
  playback::RoundTripSettings s;
  s.device = output_settings(o.device, "nibrig-latency");
  s.device.input_channel = o.input_channel;
  if (!o.input_device.empty()) {
    try {
      s.device.input_device = playback::choose_device(s.device.api, o.input_device).device.name;
    } catch (const playback::DeviceError& e) {
      throw playback::DeviceError(std::string("--input-device: ") + e.what());
    }
  }
  s.impulses = o.impulses;
  s.interval_s = o.interval_ms / 1e3;
  s.level = o.level;
  s.threshold = o.threshold;
  const auto results = playback::measure_round_trips(
      s, o.periods, [](std::size_t done, std::size_t total, const playback::RoundTripResult& r) {
        spdlog::info("latency: period {} measured ({} of {})", r.stream.period_frames, done, total);
      });
  print_latency_table(results);
  write_json_numbers(o.json, {{"impulses", o.impulses},
                              {"interval_ms", o.interval_ms},
                              {"level", o.level},
                              {"threshold", o.threshold},
                              {"periods", round_trips_json(results)}});
}

}  // namespace

void add_latency_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global) {
  auto o = std::make_shared<LatencyOptions>();
  auto* cmd = app.add_subcommand(
      "latency",
      "Measure the round trip from an output to an input (the actuator and its accelerometer, or "
      "a loopback cable) with impulses, per period");
  add_device_options(cmd, o->device);
  // The shared --period takes one period; here several are measured in one run.
  cmd->remove_option(cmd->get_option("--period"));
  cmd->add_option("--period", o->periods,
                  "Periods in frames to measure, one stream each (e.g. --period 64,128,256; JACK "
                  "runs its server's)")
      ->delimiter(',')
      ->check(whole_in_range(1, 1 << 16, "a period in frames"));
  cmd->add_option("--input-device", o->input_device,
                  "Device to record from, by name or a unique part (default: the output device)");
  cmd->add_option("--input-channel", o->input_channel,
                  "Input channel the impulses come back on (1-based)")
      ->check(whole_in_range(1, playback::kMostOutputChannels, "a channel number"));
  cmd->add_option("--impulses", o->impulses, "Impulses played per period")
      ->check(whole_in_range(1, 100000, "a number of impulses"));
  cmd->add_option("--interval", o->interval_ms,
                  "Milliseconds from one impulse to the next: the longest round trip measurable")
      ->check(in_range(20, 10000, "a time in milliseconds"));
  cmd->add_option("--level", o->level, "The impulse's peak, full scale = 1")
      ->check(in_range(1e-4, 1.0, "a level of full scale"));
  cmd->add_option("--threshold", o->threshold,
                  "Normalised correlation with the played pulse an impulse needs to count as found")
      ->check(in_range(0.01, 1.0, "a correlation in (0, 1]"));
  add_json_option(cmd, o->json, "the table");
  cmd->footer(
      "Each impulse is a 255-sample maximum-length sequence; it is found where its normalised\n"
      "cross-correlation with the input peaks after it was played. One whose peak stays under\n"
      "--threshold is counted as not found and left out of mean, sd and worst case.\n"
      "smp: samples (frames) at the stream's rate. api says: the stream's latency in frames as "
      "the\n"
      "audio back end reports it, beside what was measured.");
  cmd->callback([o, global] {
    configure_logging(global->verbosity);
    latency(*o);
  });
}

}  // namespace nibrig::ui::cli
