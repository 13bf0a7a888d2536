// `nibrig rig devices` and `nibrig rig capture`: the turntable rig from the command line. The rig,
// its profile and the capture are library calls (rig/); this file holds options and presentation.
#include <spdlog/spdlog.h>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "model/design/tool_sound.hpp"
#include "playback/audio_devices.hpp"
#include "rig/capture.hpp"
#include "rig/rig_request.hpp"
#include "rig/usb/usb_device_list.hpp"
#include "rig/usb/usb_protocol.hpp"
#include "ui/cli/commands.hpp"
#include "ui/cli/forcing_options.hpp"
#include "ui/cli/logging.hpp"
#include "ui/cli/number_checks.hpp"
#include "ui/cli/output.hpp"

namespace nibrig::ui::cli {
namespace {

struct RigOptions {
  bool simulated = false;
  std::optional<std::string> usb;  // given: the USB rig ("" = the only controller)
  std::filesystem::path replay;
  std::string tool, surface;
  std::filesystem::path catalog, design, forcing_model;
  std::string profile = "steps";
  std::optional<double> seconds;
  double load = 2.2;
  unsigned seed = 1;
  double speedup = 1.0;
  std::string input_api, input;
  unsigned input_channel = 1;
  double accelerometer = 49.05;
  std::filesystem::path output;
};

// Ctrl-C during a capture: the motor stops and the session is finished with what it holds.
std::atomic<bool> interrupted{false};
extern "C" void on_interrupt(int) { interrupted.store(true); }

void add_rig_source_options(CLI::App* cmd, RigOptions& o) {
  auto* simulated = cmd->add_flag("--simulated", o.simulated,
                                  "The simulated rig: the engine's simulation of --tool on --surface");
  auto* usb = cmd->add_option_function<std::string>(
                     "--usb", [&o](const std::string& serial) { o.usb = serial; },
                     "The USB rig controller (by serial; alone: the only one)")
                  ->expected(0, 1);
  auto* replay = cmd->add_option("--replay", o.replay,
                                 "Replay a recorded session (or a paper recording) as if live");
  simulated->excludes(usb)->excludes(replay);
  usb->excludes(replay);
  cmd->add_option("--tool", o.tool,
                  "The tool mounted (catalog id or design point); the simulated rig simulates it");
  cmd->add_option("--surface", o.surface, "The surface on the turntable (e.g. office)");
  cmd->add_option("--catalog", o.catalog, "Catalog JSON (default: the bundled one)");
  cmd->add_option("--design", o.design, "Stylus design whose modes shape catalog tools");
  cmd->add_option("--forcing", o.forcing_model, "Forcing model for design points");
  cmd->add_option("--load", o.load, "The arm's normal load in N (default 2.2, the paper's)")
      ->check(in_range(0, 50, "a load in N"));
  cmd->add_option("--seed", o.seed, "Seed of the simulated rig's noise")->check(any_seed());
  cmd->add_option("--speedup", o.speedup,
                  "Simulated and replayed rigs: 1 = real time, k = k times faster, 0 = as fast as "
                  "it computes")
      ->check(in_range(0, 1e6, "a speed-up factor"));
  cmd->add_option("--input", o.input, "USB rig: the audio input the accelerometer is on (by name)");
  cmd->add_option("--input-api", o.input_api, "USB rig: the audio back end of --input (jack, alsa, pulse)");
  cmd->add_option("--input-channel", o.input_channel, "USB rig: the accelerometer's input channel (1-based)")
      ->check(whole_in_range(1, 64, "a channel number"));
  cmd->add_option("--accelerometer", o.accelerometer,
                  "USB rig: the accelerometer's m/s² at full scale (as `calibrate --accelerometer`)")
      ->check(positive("m/s² per full scale"));
}

rig::RigRequest rig_request(const RigOptions& o) {
  rig::RigRequest r;
  if (o.usb) {
    r.kind = rig::RigKind::usb;
    r.usb_serial = *o.usb;
  } else if (!o.replay.empty()) {
    r.kind = rig::RigKind::replay;
    r.replay = o.replay;
  } else if (o.simulated) {
    r.kind = rig::RigKind::simulated;
  } else {
    throw CLI::ValidationError("rig", "say which rig: --simulated, --usb [SERIAL] or --replay SESSION");
  }
  r.tool = o.tool;
  r.surface = o.surface;
  r.load_N = o.load;
  r.seed = o.seed;
  r.speedup = o.speedup;
  r.input_api = o.input_api;
  r.input_device = o.input;
  r.input_channel = o.input_channel;
  r.accelerometer_m_s2_per_full_scale = o.accelerometer;
  return r;
}

void capture(const RigOptions& o) {
  const rig::RigRequest request = rig_request(o);
  if (request.kind == rig::RigKind::simulated && (o.tool.empty() || o.surface.empty()))
    throw CLI::ValidationError("--simulated", "the simulated rig needs --tool and --surface");
  model::design::ToolSounds sounds({o.catalog, o.design, o.forcing_model, design_progress()});
  std::optional<rig::SpeedProfile> asked;
  if (request.kind != rig::RigKind::replay) asked = rig::profile_named(o.profile, o.seconds);
  const auto rig = rig::open_rig(request, sounds);
  // A replay runs what was recorded, cut to --seconds when given.
  const rig::SpeedProfile profile =
      asked ? *asked
            : (o.seconds ? rig::fit_to_duration(*rig->own_profile(), *o.seconds) : *rig->own_profile());
  const auto& d = rig->description();
  std::printf("%s\n", d.name.c_str());
  std::printf("profile: %s, %.1f s\n", profile.description().c_str(), profile.duration_s());
  std::fflush(stdout);

  rig::CaptureOptions options;
  options.folder = o.output;
  options.tool = o.tool;
  options.surface = o.surface;
  options.cancel = &interrupted;
  options.on_progress = [](const rig::CaptureProgress& p) {
    spdlog::info("{:.0f} of {:.0f} s, {:.0f} mm/s{}", p.seconds, p.duration_s, p.speed_m_s * 1e3,
                 p.dropped_frames > 0 ? fmt::format(", {} frames dropped", p.dropped_frames) : "");
  };
  interrupted.store(false);
  const auto previous = std::signal(SIGINT, on_interrupt);
  rig::CaptureResult result;
  try {
    result = rig::capture_session(*rig, profile, options);
  } catch (...) {
    std::signal(SIGINT, previous);
    throw;
  }
  std::signal(SIGINT, previous);
  const auto& r = result.record;
  std::printf("captured %.2f s: %llu sensor frames at %.0f Hz, acceleration at %.0f Hz\n", r.seconds,
              static_cast<unsigned long long>(r.frames), d.frame_rate_hz, d.acceleration_rate_hz);
  std::printf("dropped frames %llu, saturated %llu, faults %llu; alignment error %.3f ms\n",
              static_cast<unsigned long long>(r.dropped_frames),
              static_cast<unsigned long long>(r.saturated_frames),
              static_cast<unsigned long long>(r.fault_frames), r.alignment_error_ms);
  if (!result.complete)
    std::printf("ended early (%s): the session keeps everything received\n", r.ended_because.c_str());
  std::fflush(stdout);
  say_wrote(result.folder);
}

void devices() {
  const auto controllers = rig::usb::list_rig_controllers();
  std::printf("rig controllers (USB %04x:%04x):%s\n", rig::usb::kVendorId, rig::usb::kProductId,
              controllers.empty() ? " none found" : "");
  for (const auto& c : controllers) std::printf("  %s\n", rig::usb::describe(c).c_str());
  std::printf("audio inputs (an accelerometer on an input channel):\n");
  for (const auto& api : playback::list_devices())
    std::printf("%s\n", playback::describe_devices(api).c_str());
}

}  // namespace

void add_rig_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global) {
  auto* rig_cmd = app.add_subcommand(
      "rig", "The turntable rig: list devices, capture sessions, compare with the simulation");
  rig_cmd->require_subcommand(1);

  auto* list = rig_cmd->add_subcommand("devices", "USB rig controllers and audio inputs, by name");
  list->callback([global] {
    configure_logging(global->verbosity);
    devices();
  });

  auto options = std::make_shared<RigOptions>();
  auto* cap = rig_cmd->add_subcommand(
      "capture", "Run a speed profile on a rig and record a session (measure it with `nibrig measure`)");
  add_rig_source_options(cap, *options);
  auto* profile = cap->add_option("--profile", options->profile,
                  "steps (the paper's: 3 sweeps of six 2 s steps over 17-250 mm/s), sweep (the "
                  "study's 3 s sweep) or a CSV file time_s,speed_mm_s");
  profile->excludes(cap->get_option("--replay"));
  cap->add_option_function<double>(
         "--seconds", [o = options.get()](const double& s) { o->seconds = s; },
         "Length: cuts or repeats the profile (default: steps 42 s, sweep 6 s, a file its own)")
      ->check(positive("a length in seconds"));
  cap->add_option("-o,--output", options->output,
                  "Session folder to write (<folder>.partial while recording)")
      ->required();
  cap->callback([options, global] {
    configure_logging(global->verbosity);
    capture(*options);
  });
}

}  // namespace nibrig::ui::cli
