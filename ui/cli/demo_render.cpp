#include "ui/cli/demo_render.hpp"

#include <algorithm>
#include <optional>
#include <thread>
#include <chrono>
#include <cstdio>
#include <set>
#include <sstream>

#include "playback/audio_devices.hpp"
#include "playback/audio_output.hpp"
#include "model/design/tool_sound.hpp"
#include "playback/live_audition.hpp"
#include "playback/offline_render.hpp"
#include "playback/prepared_engine.hpp"
#include "ui/cli/output.hpp"
#include "ui/cli/progress.hpp"

namespace nibrig::ui::cli {
namespace {

// The surface a tool is heard on: plain office paper where it was measured, else the first
// surface in this order, else whatever it has.
std::string preferred_surface(const model::io::Catalog& catalog, const std::string& tool) {
  const std::vector<std::string> order{"office", "note", "paperlike", "stone", "glass", "protector"};
  std::set<std::string> has;
  for (const auto& p : catalog.pairings)
    if (p.tool == tool && p.vibration) has.insert(p.surface);
  for (const auto& s : order)
    if (has.count(s)) return s;
  return has.empty() ? "" : *has.begin();
}

// The first API with an output device, or nothing: the demo needs no hardware, and plays only
// when there is something to play on.
std::optional<playback::OutputSettings> available_output() {
  for (const auto& api : playback::list_devices())
    for (const auto& d : api.devices)
      if (api.available && d.output_channels > 0) {
        playback::OutputSettings s;
        s.api = api.api;
        s.device = d.name;
        s.sample_rate = d.preferred_sample_rate > 0 ? d.preferred_sample_rate : 48000;
        s.period_frames = 64;
        s.stream_name = "nibrig-demo";
        return s;
      }
  return std::nullopt;
}

// A tool's sound moved by the rig's sweep, in an engine of its own.
playback::PreparedEngine sweep_engine(const model::design::ToolSound& sound, double sample_rate_hz) {
  rt::EngineSettings settings;
  settings.sample_rate_hz = sample_rate_hz;
  return playback::PreparedEngine(settings, sound, std::make_unique<rt::SweepStroke>(), 1);
}

// Each tool for one sweep through the device, one after another, each from the sweep's start.
DemoSection play_all(model::design::ToolSounds& sounds,
                     const std::vector<std::pair<std::string, std::string>>& pairs,
                     const playback::OutputSettings& device) {
  rt::EngineSettings settings;
  settings.sample_rate_hz = device.sample_rate;
  settings.slots = 1;
  playback::LiveAudition audition(settings);
  audition.open(device);
  for (const auto& [tool, surface] : pairs) {
    audition.load(0, sounds.sound(tool, surface), 1);
    audition.attach(std::make_unique<rt::SweepStroke>());
    std::printf("playing %s on %s\n", tool.c_str(), surface.c_str());
    std::this_thread::sleep_for(std::chrono::duration<double>(rt::SweepStroke::kPaperPeriod));
    audition.pump();
  }
  const std::uint64_t overruns = audition.engine_stats().overruns;
  const std::uint64_t underflows = audition.output_stats()->output_underflows;
  return {"  played every tool through " + device.api + " '" + device.device + "': " +
              std::to_string(overruns) + " engine overruns, " + std::to_string(underflows) +
              " device underflows\n",
          {{"api", device.api},
           {"device", device.device},
           {"engine_overruns", overruns},
           {"device_underflows", underflows}}};
}

}  // namespace

DemoSection run_render_demo(const model::io::Catalog& catalog,
                            const std::filesystem::path& catalog_file,
                            const std::filesystem::path& report) {
  const auto folder = report / "render";
  ensure_folder(folder);
  model::design::ToolSounds sounds({catalog_file, "", "", {}});
  std::vector<std::pair<std::string, std::string>> pairs;
  for (const auto& t : catalog.tools)
    if (auto s = preferred_surface(catalog, t.id); !s.empty()) pairs.emplace_back(t.id, s);

  std::ostringstream table;
  table << "tool,surface,peak_full_scale,rms_m_s2,realtime_factor\n";
  Progress progress("renders", pairs.size());
  double slowest = 1e300, loudest = 0;
  std::string loudest_name, modes;
  for (const auto& [tool, surface] : pairs) {
    const model::design::ToolSound sound = sounds.sound(tool, surface);
    modes = sound.modes;  // the same stylus for every catalog tool
    auto session = sweep_engine(sound, rt::EngineSettings{}.sample_rate_hz);
    const double seconds = rt::SweepStroke::kPaperPeriod;
    const std::size_t block_frames = playback::OfflineRenderSettings{}.block_frames;
    const auto start = std::chrono::steady_clock::now();
    const auto r = session.render_to_wav(folder / (tool + "_" + surface + ".wav"), seconds, block_frames);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double rms_m_s2 = r.rms / rt::EngineSettings{}.output_level_per_m_s2;
    table << tool << ',' << surface << ',' << r.peak << ',' << rms_m_s2 << ',' << seconds / wall << '\n';
    slowest = std::min(slowest, seconds / wall);
    if (rms_m_s2 > loudest) loudest = rms_m_s2, loudest_name = tool + " on " + surface;
    progress.advance(tool);
  }
  write_text_file(folder / "renders.csv", table.str());
  DemoSection played{"  no audio device: nothing played (see `nibrig devices`)\n", nullptr};
  if (const auto device = available_output()) played = play_all(sounds, pairs, *device);
  const rt::EngineSettings engine_settings;
  char line[500];
  std::snprintf(line, sizeof line,
                "real-time engine: %zu tools rendered over one sweep (%.0f -> %.0f -> %.0f mm/s, "
                "%.0f s) through the modes of '%s' at %.0f Hz, %zu-frame blocks;\n  loudest %s at "
                "%.2f m/s^2 rms; slowest render %.0fx real time (WAV writing included)\n"
                "  report: render/*.wav, render/renders.csv\n",
                pairs.size(), 1e3 * rt::SweepStroke::kPaperLow, 1e3 * rt::SweepStroke::kPaperHigh,
                1e3 * rt::SweepStroke::kPaperLow, rt::SweepStroke::kPaperPeriod, modes.c_str(),
                engine_settings.sample_rate_hz, playback::OfflineRenderSettings{}.block_frames,
                loudest_name.c_str(), loudest, slowest);
  return {line + played.text,
          {{"tools", pairs.size()},
           {"seconds_each", rt::SweepStroke::kPaperPeriod},
           {"sample_rate_hz", engine_settings.sample_rate_hz},
           {"loudest", loudest_name},
           {"loudest_rms_m_s2", loudest},
           {"slowest_realtime_factor", slowest},
           {"played", played.numbers}}};
}

}  // namespace nibrig::ui::cli
