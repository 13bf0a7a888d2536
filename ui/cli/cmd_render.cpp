// `nibrig render`: a tool on a surface, moved as asked, rendered offline through the real-time
// engine (the same render() the audio callback calls) into a WAV file.
#include <spdlog/spdlog.h>

#include <chrono>
#include <cstdio>

#include "playback/offline_render.hpp"
#include "rt/engine.hpp"
#include "ui/cli/commands.hpp"
#include "ui/cli/logging.hpp"
#include "ui/cli/number_checks.hpp"
#include "ui/cli/stroke_options.hpp"
#include "ui/cli/tool_voice.hpp"

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
  const auto catalog = voice_catalog(o.stroke.catalog);
  const bool predicted = names_design_point(o.stroke.tool);
  if (!predicted) pairing_spectrum(catalog, o.stroke.catalog, o.stroke.tool, o.stroke.surface);
  rt::EngineSettings settings;
  settings.sample_rate_hz = o.rate;
  rt::Engine engine(settings);
  std::unique_ptr<rt::Voice> voice;
  std::string modes;
  if (predicted) {
    DesignPredictor predictor(o.stroke.catalog, o.stroke.forcing_model);
    const auto tool = predictor.predict(o.stroke.tool, o.stroke.surface);
    voice = predicted_voice(tool, engine.internal_rate(), o.stroke.seed);
    modes = tool.design_name;
  } else {
    const StylusModes stylus = stylus_modes(o.stroke.design);
    voice = tool_voice(catalog, o.stroke.catalog, o.stroke.tool, o.stroke.surface, stylus,
                       engine.internal_rate(), o.stroke.seed);
    modes = stylus.name;
  }
  const std::string name = voice->name();
  engine.load(0, std::move(voice));
  engine.select(0);
  Stroke stroke = make_stroke(o.stroke);
  engine.attach(std::move(stroke.source));

  playback::OfflineRenderSettings render_settings;
  render_settings.sample_rate_hz = o.rate;
  render_settings.block_frames = o.period;
  render_settings.seconds = o.seconds > 0 ? o.seconds : stroke.natural_seconds;
  const auto start = std::chrono::steady_clock::now();
  const auto result = playback::render_to_wav(engine, o.output, render_settings);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto stats = engine.stats();
  std::printf("%s through %s, %s\n", name.c_str(), modes.c_str(), stroke.description.c_str());
  std::printf("wrote %s: %.2f s at %.0f Hz (%zu frames in %zu-frame blocks)\n", o.output.c_str(),
              render_settings.seconds, o.rate, result.frames, o.period);
  std::printf("level: peak %.4f, rms %.4f of full scale (%.3g m/s² rms at %.3g per m/s², uncalibrated)\n",
              result.peak, result.rms, result.rms / settings.output_level_per_m_s2,
              settings.output_level_per_m_s2);
  std::printf("limited samples %llu, non-finite %llu; internal samples above the measured speeds %llu\n",
              static_cast<unsigned long long>(stats.limited_samples),
              static_cast<unsigned long long>(stats.non_finite_samples),
              static_cast<unsigned long long>(stats.samples_above_speed_range));
  std::printf("render: %.3f s wall, %.0fx real time; per block median <= %.1f us, 99th percentile <= %.1f us\n",
              wall, render_settings.seconds / wall, 1e6 * stats.callback_time_quantile(0.5),
              1e6 * stats.callback_time_quantile(0.99));
}

}  // namespace

void add_render_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global) {
  auto options = std::make_shared<RenderOptions>();
  auto* cmd = app.add_subcommand(
      "render", "Render a tool on a surface through the real-time engine into a WAV file");
  add_stroke_options(cmd, options->stroke);
  cmd->add_option("-o,--output", options->output, "WAV file to write (mono, float)")->required();
  cmd->add_option("--seconds", options->seconds,
                  "Length (default: two sweep periods, the trajectory's length, or 5 s)")
      ->check(positive("a length in seconds"));
  // The voices run at about 8 kHz (rt/engine.hpp): a device rate below that cannot carry them.
  cmd->add_option("--rate", options->rate, "Sample rate in Hz")
      ->check(in_range(8000, 384000, "a sample rate in Hz"));
  cmd->add_option("--period", options->period, "Block size in frames, as a device period")
      ->check(whole_in_range(1, 1 << 16, "a block size in frames"));
  cmd->callback([options, global] {
    configure_logging(global->verbosity);
    for (const auto& note : outside_measured_range(options->stroke)) spdlog::warn("{}", note);
    render(*options);
  });
}

}  // namespace nibrig::ui::cli
