// `nibrig rig devices`, `nibrig rig capture` and `nibrig rig compare`: the turntable rig from the
// command line. The rig, its profile, the capture, the comparison and the actuator following the
// turntable are library calls (rig/); this file holds options and presentation.
#include <spdlog/spdlog.h>

#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "model/design/tool_sound.hpp"
#include "model/io/comparison_file.hpp"
#include "playback/audio_devices.hpp"
#include "rig/accelerometer_input.hpp"
#include "rig/actuator_player.hpp"
#include "rig/capture.hpp"
#include "rig/comparison_report.hpp"
#include "rig/comparison_run.hpp"
#include "rig/comparison_start.hpp"
#include "rig/pacer.hpp"
#include "rig/rig_request.hpp"
#include "rig/usb/bootloader_port.hpp"
#include "rig/usb/usb_device_list.hpp"
#include "rig/usb/usb_protocol.hpp"
#include "ui/cli/app.hpp"
#include "ui/cli/commands.hpp"
#include "ui/cli/device_json.hpp"
#include "ui/cli/device_options.hpp"
#include "ui/cli/forcing_options.hpp"
#include "ui/cli/interrupt_scope.hpp"
#include "ui/cli/logging.hpp"
#include "ui/cli/output.hpp"
#include "ui/cli/rig_figures.hpp"
#include "ui/options/number_checks.hpp"

namespace nibrig::ui::cli {
namespace {

struct RigOptions {
  bool simulated = false;
  std::optional<std::string> usb;  // given: the USB rig ("" = the only controller)
  rig::RigRequest request;         // the options bound to it; its kind set from the three above
  std::string design;  // what to simulate instead of the mounted tool: a design point or a tool id
  std::filesystem::path catalog, stylus, forcing_model;
  std::string profile;  // empty: the command's default
  std::optional<double> seconds;
  bool play = false;
  DeviceOptions device;
  std::string actuator;
  std::filesystem::path output;  // capture: the session; compare: the report folder
};

void add_rig_source_options(CLI::App* cmd, RigOptions& o) {
  auto* simulated = cmd->add_flag("--simulated", o.simulated,
                                  "The simulated rig: the engine's simulation of --tool on --surface");
  auto* usb = cmd->add_option_function<std::string>(
                     "--usb", [&o](const std::string& serial) { o.usb = serial; },
                     "The USB rig controller (by serial; alone: the only one)")
                  ->expected(0, 1);
  auto* replay = cmd->add_option("--replay", o.request.replay,
                                 "Replay a recorded session (or a paper recording) as if live");
  simulated->excludes(usb)->excludes(replay);
  usb->excludes(replay);
  cmd->add_option("--tool", o.request.tool,
                  "The tool mounted (catalog id or design point); the simulated rig simulates it");
  cmd->add_option("--surface", o.request.surface, "The surface on the turntable (e.g. office)");
  cmd->add_option("--catalog", o.catalog, "Catalog JSON (default: the bundled one)");
  cmd->add_option("--stylus", o.stylus,
                  "Stylus design JSON whose modes shape catalog tools (default: the bundled 2 mm one)");
  cmd->add_option("--forcing", o.forcing_model, "Forcing model for design points");
  cmd->add_option("--profile", o.profile,
                  "steps (the paper's: 3 sweeps of six 2 s steps over 17-250 mm/s), sweep (the "
                  "study's 3 s sweep) or a CSV file time_s,speed_mm_s")
      ->excludes(replay);
  cmd->add_option_function<double>(
         "--seconds", [&o](const double& s) { o.seconds = s; },
         "Length: cuts or repeats the profile (default: steps 42 s, sweep 6 s, a file its own)")
      ->check(in_range(rig::kShortestCaptureSeconds, rig::kMaxProfileSeconds, "a length in seconds"));
  cmd->add_option("--load", o.request.load_N, "The arm's normal load in N (the paper's by default)")
      ->capture_default_str()
      ->check(in_range(rig::kLightestLoadN, rig::kHeaviestLoadN, "a load in N"));
  cmd->add_option("--seed", o.request.seed, "Seed of the simulated rig's noise")->check(any_seed());
  cmd->add_option("--speedup", o.request.speedup,
                  "Simulated and replayed rigs: 1 = real time, k = k times faster, 0 = as fast as "
                  "it computes")
      ->check(
          off_or_in_range(rig::Pacer::kMinSpeedup, rig::Pacer::kMaxSpeedup, "a speed-up factor"));
  cmd->add_option("--input", o.request.input_device,
                  "USB rig: the audio input the accelerometer is on (by name)");
  cmd->add_option("--input-api", o.request.input_api,
                  "USB rig: the audio back end of --input (jack, alsa, pulse)");
  cmd->add_option("--input-channel", o.request.input_channel,
                  "USB rig: the accelerometer's input channel (1-based)")
      ->check(whole_in_range(1, playback::kMostOutputChannels, "a channel number"));
  cmd->add_option(
         "--accelerometer", o.request.accelerometer_m_s2_per_full_scale,
         "USB rig: the accelerometer's m/s² at full scale (as `calibrate --accelerometer`)")
      ->check(in_range(rig::kLeastAccelerometerM_s2, rig::kMostAccelerometerM_s2,
                       "m/s² per full scale"));
  auto* play = cmd->add_flag("--play", o.play,
                             "Play the simulated tool on the actuator, following the turntable");
  add_device_options(cmd, o.device);
  cmd->add_option("--actuator", o.actuator,
                  "With --play: the actuator calibration from `nibrig calibrate` (name or file)")
      ->needs(play);
}

// The request the options were bound to, of the rig they name.
rig::RigRequest rig_request(const RigOptions& o) {
  rig::RigRequest r = o.request;
  if (o.usb) {
    r.kind = rig::RigKind::usb;
    r.usb_serial = *o.usb;
  } else if (!o.request.replay.empty()) {
    r.kind = rig::RigKind::replay;
  } else if (o.simulated) {
    r.kind = rig::RigKind::simulated;
  } else {
    throw CLI::ValidationError("rig", "say which rig: --simulated, --usb [SERIAL] or --replay SESSION");
  }
  return r;
}

// A refused rig request as the option at fault.
[[noreturn]] void throw_as_option(const rig::RigRequestRefused& e) {
  using Field = rig::RigRequestRefused::Field;
  const char* option = "rig";
  switch (e.field()) {
    case Field::rig:
      break;
    case Field::tool:
      option = "--tool";
      break;
    case Field::surface:
      option = "--surface";
      break;
    case Field::load:
      option = "--load";
      break;
    case Field::speedup:
      option = "--speedup";
      break;
    case Field::accelerometer:
      option = "--accelerometer";
      break;
    case Field::input_channel:
      option = "--input-channel";
      break;
    case Field::replay:
      option = "--replay";
      break;
    case Field::profile:
      option = "--profile";
      break;
    case Field::seconds:
      option = "--seconds";
      break;
    case Field::simulate:
      option = "--design";
      break;
  }
  throw CLI::ValidationError(option, e.what());
}

// What the simulation is asked to play: --design when given, else --tool (else the mounted tool).
const std::string& simulated_asked(const RigOptions& o) {
  return o.design.empty() ? o.request.tool : o.design;
}

// --play: the simulated tool on the actuator, following the turntable (rig/actuator_player.hpp),
// saying what it plays on before the run and how closely it followed after it.
std::unique_ptr<rig::ActuatorPlayer> play_on_actuator(const RigOptions& o, const model::design::ToolSound& sound,
                                                      rig::Rig& rig) {
  rig::ActuatorPlayerSettings settings;
  settings.device = output_settings(o.device, "nibrig-rig-play");
  settings.actuator = o.actuator;
  settings.seed = o.request.seed;
  auto player = std::make_unique<rig::ActuatorPlayer>(rig, sound, settings);
  if (const auto& calibration = player->actuator())
    std::printf("actuator '%s': inverse filter flat to %.2f dB over %.0f-%.0f Hz\n",
                calibration->name.c_str(), player->inverse_filter()->max_deviation_db,
                calibration->design.band_low_hz, calibration->design.band_high_hz);
  player->play();
  const auto info = *player->stream_info();
  std::printf("playing %s on %s '%s' channel %u, %u-frame periods, following the turntable\n",
              sound.name.c_str(), info.api.c_str(), info.device.c_str(), settings.device.output_channel,
              info.period_frames);
  return player;
}

model::io::ComparisonActuator report_following(const rig::ActuatorPlayer& player) {
  const rig::FollowLatency l = player.latency();
  const auto info = *player.stream_info();
  const model::io::ComparisonActuator following{
      l.contacts, l.mean_s, l.max_s, static_cast<double>(info.period_frames) / info.sample_rate};
  std::printf(
      "actuator followed %llu contacts: from frame to engine mean %.2f ms, max %.2f ms "
      "(one period is %.2f ms)\n",
      static_cast<unsigned long long>(l.contacts), l.mean_s * 1e3, l.max_s * 1e3,
      1e3 * following.period_s);
  return following;
}

void print_record(const rig::CaptureResult& result, const rig::RigDescription& d) {
  const auto& r = result.record;
  std::printf("captured %.2f s: %llu sensor frames at %.0f Hz, acceleration at %.0f Hz\n", r.seconds,
              static_cast<unsigned long long>(r.frames), d.frame_rate_hz, d.acceleration_rate_hz);
  std::printf("dropped frames %llu, saturated %llu, faults %llu; alignment error %.3f ms\n",
              static_cast<unsigned long long>(r.dropped_frames),
              static_cast<unsigned long long>(r.saturated_frames),
              static_cast<unsigned long long>(r.fault_frames), r.alignment_error_ms);
  if (!result.complete)
    std::printf("ended early (%s): the session keeps everything received\n", r.ended_because.c_str());
}

model::design::ToolSoundOptions sound_options(const RigOptions& o) {
  return {o.catalog, o.stylus, o.forcing_model, design_progress()};
}

void capture(const RigOptions& o) {
  model::design::ToolSounds sounds(sound_options(o));
  rig::OpenedRig opened = [&] {
    try {
      return rig::open_rig_with_profile(rig_request(o), sounds, o.profile, "steps", o.seconds);
    } catch (const rig::RigRequestRefused& e) {
      throw_as_option(e);
    }
  }();
  rig::Rig& rig = *opened.rig;
  std::printf("%s\nprofile: %s, %.1f s\n", rig.description().name.c_str(),
              opened.profile.description().c_str(), opened.profile.duration_s());
  std::fflush(stdout);
  std::unique_ptr<rig::ActuatorPlayer> player;
  if (o.play) {
    const auto simulated =
        rig::simulated_choice(rig.description(), simulated_asked(o), o.request.surface);
    sounds.check(simulated.tool, simulated.surface);
    player = play_on_actuator(o, sounds.sound(simulated.tool, simulated.surface), rig);
  }
  rig::CaptureOptions options;
  options.folder = o.output;
  options.tool = o.request.tool;
  options.surface = o.request.surface;
  options.on_progress = [](const rig::CaptureProgress& p) {
    spdlog::info("{:.0f} of {:.0f} s, {:.0f} mm/s{}", p.seconds, p.duration_s, p.speed_m_s * 1e3,
                 p.dropped_frames > 0 ? fmt::format(", {} frames dropped", p.dropped_frames) : "");
  };
  InterruptScope scope;
  options.cancel = scope.token();
  const rig::CaptureResult result = rig::capture_session(rig, opened.profile, options);
  print_record(result, rig.description());
  if (player) report_following(*player);
  std::fflush(stdout);
  say_wrote(result.folder);
  if (scope.interrupted())
    throw Interrupted("the capture was stopped; what it recorded is kept in " +
                      result.folder.string());
}

void compare(const RigOptions& o) {
  rig::ComparisonRequest request;
  request.rig = rig_request(o);
  request.profile = o.profile;
  request.seconds = o.seconds;
  request.simulate = o.design;
  request.sounds = sound_options(o);
  request.session = o.output / "session";
  request.seed = o.request.seed;
  std::optional<rig::ComparisonStart> start;
  try {
    start.emplace(std::move(request));
    start->open();
  } catch (const rig::RigRequestRefused& e) {
    throw_as_option(e);
  }
  rig::Rig& rig = start->rig();
  const model::design::ToolSound& simulated = start->simulated();
  std::printf("%s\nsimulated: %s (modes of %s)\nprofile: %s, %.1f s\n",
              rig.description().name.c_str(), simulated.name.c_str(), simulated.modes.c_str(),
              start->profile().description().c_str(), start->profile().duration_s());
  std::fflush(stdout);
  std::unique_ptr<rig::ActuatorPlayer> player;
  if (o.play) player = play_on_actuator(o, simulated, rig);

  ensure_folder(o.output);
  InterruptScope scope;
  rig::ComparisonHooks hooks;
  hooks.cancel = scope.token();
  hooks.on_progress = [](const rig::CaptureProgress& p) {
    spdlog::info("{:.0f} of {:.0f} s, {:.0f} mm/s", p.seconds, p.duration_s, p.speed_m_s * 1e3);
  };
  const rig::ComparisonRun run = start->run(hooks);
  print_record(run.capture, rig.description());
  model::io::ComparisonFile report = start->report(run);
  if (player) report.actuator = report_following(*player);
  print_comparison_table(run.table);
  std::fflush(stdout);

  const auto json = o.output / "comparison.json";
  model::io::write_comparison_file(report, json);
  const auto png = o.output / "comparison.png";
  write_comparison_figure(
      run, start->measured_tool() + " on " + start->surface() + " against " + simulated.name, png);
  say_wrote(run.capture.folder);
  say_wrote(json);
  say_wrote(png);
  if (scope.interrupted())
    throw Interrupted("the capture was stopped; the comparison covers what it recorded");
}

void list_rig_controllers(const std::filesystem::path& json) {
  const auto controllers = rig::usb::list_rig_controllers();
  std::printf("rig controllers (USB %04x:%04x):%s\n", rig::usb::kVendorId, rig::usb::kProductId,
              controllers.empty() ? " none found" : "");
  for (const auto& c : controllers) std::printf("  %s\n", rig::usb::describe(c).c_str());
  // A board whose reset was just pressed waits in its bootloader for `rig flash --port`.
  const auto waiting = rig::usb::bootloader_ports();
  if (!waiting.empty()) {
    std::printf("bootloaders waiting for an upload (`nibrig rig flash --port PORT`):\n");
    for (const auto& p : waiting) std::printf("  %s\n", rig::usb::describe(p).c_str());
  }
  std::printf("audio inputs (an accelerometer on an input channel):\n");
  const auto apis = playback::list_devices();
  for (const auto& api : apis) std::printf("%s\n", playback::describe_devices(api).c_str());
  write_json_numbers(json, {{"controllers", rig_controllers_json(controllers)},
                            {"bootloaders", serial_ports_json(waiting)},
                            {"audio", audio_devices_json(apis)}});
}

}  // namespace

void add_rig_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global) {
  auto* rig_cmd = app.add_subcommand(
      "rig", "The turntable rig: list devices, capture sessions, compare with the simulation, set up and "
             "flash a USB controller");
  rig_cmd->require_subcommand(1);

  auto* list = rig_cmd->add_subcommand("devices", "USB rig controllers and audio inputs, by name");
  auto list_json = std::make_shared<std::filesystem::path>();
  add_json_option(list, *list_json, "the list");
  list->callback([global, list_json] {
    configure_logging(global->verbosity);
    list_rig_controllers(*list_json);
  });

  auto capture_options = std::make_shared<RigOptions>();
  auto* cap = rig_cmd->add_subcommand(
      "capture", "Run a speed profile on a rig and record a session (measure it with `nibrig measure`)");
  add_rig_source_options(cap, *capture_options);
  cap->add_option("--design", capture_options->design,
                  "With --play: simulate this (a design point or tool id) instead of --tool");
  cap->add_option("-o,--output", capture_options->output,
                  "Session folder to write (<folder>.partial while recording)")
      ->required();
  cap->callback([capture_options, global] {
    configure_logging(global->verbosity);
    capture(*capture_options);
  });

  auto compare_options = std::make_shared<RigOptions>();
  auto* cmp = rig_cmd->add_subcommand(
      "compare",
      "Capture on a rig while simulating the same tool driven by the measured speed; compare their "
      "spectrograms per speed (default profile: the study's sweep)");
  add_rig_source_options(cmp, *compare_options);
  cmp->add_option("--design", compare_options->design,
                  "Simulate this instead of --tool: a design point (\"DM85:0.5,vero:0.5,tip=2mm\") or a tool id");
  cmp->add_option("--report", compare_options->output,
                  "Folder for the report: comparison.json, comparison.png and the captured session")
      ->required();
  cmp->callback([compare_options, global] {
    configure_logging(global->verbosity);
    compare(*compare_options);
  });

  add_rig_setup_commands(rig_cmd, global);
  add_rig_parts_command(rig_cmd, global);
}

}  // namespace nibrig::ui::cli
