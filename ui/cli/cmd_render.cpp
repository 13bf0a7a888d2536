// `nibrig render`: a tool on a surface, moved as asked, rendered offline through the real-time
// engine (the same render() the audio callback calls) into a WAV file.
#include <spdlog/spdlog.h>

#include <chrono>
#include <cstdio>

#include "model/design/tool_sound.hpp"
#include "playback/prepared_engine.hpp"
#include "ui/cli/commands.hpp"
#include "ui/cli/logging.hpp"
#include "ui/options/number_checks.hpp"
#include "ui/cli/output.hpp"
#include "ui/cli/stroke_options.hpp"

namespace nibrig::ui::cli {
namespace {

struct RenderOptions {
  StrokeOptions stroke;
  std::filesystem::path output;
  double seconds = 0;  // 0 = the stroke's natural length
  double rate = 48000;
  std::size_t period = 64;
};

void render(const RenderOptions& o) {
  model::design::ToolSounds sounds(tool_sound_options(o.stroke));
  sounds.check(o.stroke.tool, o.stroke.surface);  // before any meshing or fitting
  rt::Stroke stroke = make_stroke(o.stroke);       // a bad trajectory file too
  const model::design::ToolSound sound = sounds.sound(o.stroke.tool, o.stroke.surface);
  rt::EngineSettings settings;
  settings.sample_rate_hz = o.rate;
  playback::PreparedEngine session(settings, sound, std::move(stroke.source), o.stroke.seed);
  const std::string& name = session.names().front();
  const std::string& modes = sound.modes;
  const double seconds = o.seconds > 0 ? o.seconds : stroke.natural_seconds;
  ensure_folder(o.output.parent_path());  // like every command: a missing folder is created
  const auto start = std::chrono::steady_clock::now();
  const auto result = session.render_to_wav(o.output, seconds, o.period);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto stats = session.engine().stats();
  std::printf("%s through %s, %s\n", name.c_str(), modes.c_str(), stroke.description.c_str());
  std::printf("%.2f s at %.0f Hz (%zu frames in %zu-frame blocks)\n", seconds, o.rate,
              result.frames, o.period);
  std::printf("level: peak %.4f, rms %.4f of full scale (%.3g m/s² rms at %.3g per m/s², uncalibrated)\n",
              result.peak, result.rms, result.rms / settings.output_level_per_m_s2,
              settings.output_level_per_m_s2);
  std::printf("limited samples %llu, non-finite %llu; internal samples above the measured speeds %llu\n",
              static_cast<unsigned long long>(stats.limited_samples),
              static_cast<unsigned long long>(stats.non_finite_samples),
              static_cast<unsigned long long>(stats.samples_above_speed_range));
  std::printf("render: %.3f s wall, %.0fx real time; per block median <= %.1f us, 99th percentile <= %.1f us\n",
              wall, seconds / wall, 1e6 * stats.callback_time_quantile(0.5),
              1e6 * stats.callback_time_quantile(0.99));
  std::fflush(stdout);  // printf and std::cout share stdout: keep the lines in order
  say_wrote(o.output);
}

}  // namespace

void add_render_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global) {
  auto options = std::make_shared<RenderOptions>();
  auto* cmd = app.add_subcommand(
      "render", "Render a tool on a surface through the real-time engine into a WAV file");
  add_stroke_options(cmd, options->stroke);
  cmd->add_option("-o,--output", options->output, "WAV file to write (mono, float)")
      ->required()
      ->check(file_to_write());
  cmd->add_option("--seconds", options->seconds,
                  "Length (default: two sweep periods, the trajectory's length, or 5 s)")
      ->check(in_range(playback::kShortestRenderSeconds, playback::kLongestRenderSeconds,
                       "a length in seconds"));
  // The library's ranges (playback/offline_render.hpp), checked here to name the option.
  cmd->add_option("--rate", options->rate, "Sample rate in Hz")
      ->check(in_range(playback::kLowestRenderRateHz, playback::kHighestRenderRateHz, "a sample rate in Hz"));
  cmd->add_option("--period", options->period, "Block size in frames, as a device period")
      ->check(whole_in_range(1, static_cast<long long>(playback::kLargestRenderBlock), "a block size in frames"));
  cmd->callback([options, global] {
    configure_logging(global->verbosity);
    for (const auto& note : outside_measured_range(options->stroke)) spdlog::warn("{}", note);
    render(*options);
  });
}

}  // namespace nibrig::ui::cli
