// `nibrig devices`, `nibrig audition` and `nibrig calibrate`: the commands that touch an audio
// device. Audition plays a tool (or switches between up to three, as an A/B or triplet
// presentation would) through the real-time engine; calibrate measures an actuator and stores its
// inverse filter, which audition then applies.
#include <spdlog/spdlog.h>

#include <cstdio>

#include "model/design/tool_sound.hpp"
#include "playback/actuator_store.hpp"
#include "playback/alternation.hpp"
#include "playback/audio_devices.hpp"
#include "playback/audio_output.hpp"
#include "playback/calibration_run.hpp"
#include "playback/live_audition.hpp"
#include "rig/pen/pen_clock.hpp"
#include "rig/pen/pen_input.hpp"
#include "rig/pen/pen_play.hpp"
#include "rig/pen/stroke_recorder.hpp"
#include "ui/cli/commands.hpp"
#include "ui/cli/device_json.hpp"
#include "ui/cli/device_options.hpp"
#include "ui/cli/logging.hpp"
#include "ui/cli/output.hpp"
#include "ui/cli/stream_json.hpp"
#include "ui/cli/stroke_options.hpp"
#include "ui/options/number_checks.hpp"

namespace nibrig::ui::cli {
namespace {

struct AuditionOptions {
  StrokeOptions stroke;
  DeviceOptions device;
  std::vector<std::string> also;
  double switch_every = 2.0;
  double seconds = 0;
  std::string actuator;
  std::string pen, pen_name;           // a tablet's pen drives the engine instead of the stroke
  std::filesystem::path record_folder;  // with --pen: each recording's file goes there
  std::filesystem::path json;           // the numbers printed, for a script
};

struct CalibrateOptions {
  std::string name;
  DeviceOptions device;
  unsigned input_channel = 1;
  double accelerometer = 1.0;
  std::filesystem::path output;
};

void devices(const std::filesystem::path& json) {
  const auto apis = playback::list_devices();
  for (const auto& api : apis) std::printf("%s\n", playback::describe_devices(api).c_str());
  std::string why;
  const auto tablets = rig::pen::list_tablets(&why);
  std::printf("pen tablets (choose with --pen NAME):%s\n", tablets.empty() ? (" none" + (why.empty() ? "" : " (" + why + ")")).c_str() : "");
  for (const auto& t : tablets) {
    std::printf("  \"%s\"%s  %s  %.1f x %.1f mm, %s, %s\n", t.name.c_str(),
                t.model.empty() ? "" : (" (" + t.model + ")").c_str(), t.devnode.c_str(), t.width_mm, t.height_mm,
                t.has_pressure ? "pressure" : "no pressure", t.has_tilt ? "tilt" : "no tilt");
  }
  if (json.empty()) return;
  nlohmann::json out = tablets_json(tablets, why);
  out["audio"] = audio_devices_json(apis);
  write_json_numbers(json, out);
}

// The engine follows the pen until --seconds pass or the tablet goes; each stroke on its own line,
// and with --record each stroke of the session in one drawing file. Strokes are timed from
// `started_s`, on the pen's clock: when the stream opened, so that a stroke drawn as soon as the
// output appears is not timed before the audition began.
nlohmann::json play_with_pen(playback::LiveAudition& audition, rig::pen::PenStylus& pen,
                             const AuditionOptions& o, double started_s) {
  const auto& t = pen.tablet();
  const auto& curve = pen.curve();
  std::printf("pen: \"%s\" (%.1f x %.1f mm); force from %s\n", t.name.c_str(), t.width_mm, t.height_mm,
              curve.is_default ? "the default pressure curve (0 to 4.9 N; `nibrig pen calibrate` measures one)"
                               : ("the calibration " + curve.file.string()).c_str());
  std::unique_ptr<rig::pen::StrokeRecorder> recorder;
  if (!o.record_folder.empty()) {
    rig::pen::StrokeRecorderSettings settings;
    settings.folder = o.record_folder;
    settings.tool = o.stroke.tool;
    settings.surface = o.stroke.surface;
    settings.pen = o.pen_name.empty() ? t.name : o.pen_name;
    recorder = std::make_unique<rig::pen::StrokeRecorder>(settings);
    pen.on_sample([r = recorder.get()](const rig::pen::PenSample& s, double force_n) { r->add(s, force_n); });
    std::printf("recording to %s\n", recorder->start().string().c_str());
  }
  nlohmann::json strokes = nlohmann::json::array();
  rig::pen::PenPlayEvents events;
  events.stroke = [&strokes, started_s](const rig::pen::PenStrokeNote& note) {
    strokes.push_back(
        {{"stroke", note.stroke},
         {"event", note.began ? "began" : "ended"},
         {"why", note.began ? nlohmann::json(nullptr)
                            : nlohmann::json(rig::pen::pen_stroke_end_name(note.why))},
         {"at_s", note.time_s - started_s}});
    if (note.began) {
      std::printf("stroke %llu began\n", static_cast<unsigned long long>(note.stroke));
    } else {
      std::printf("stroke %llu ended (%s)\n", static_cast<unsigned long long>(note.stroke),
                  rig::pen::pen_stroke_end_name(note.why));
    }
    std::fflush(stdout);
  };
  bool removed = false;
  events.removed = [&removed] {
    removed = true;
    std::printf("the tablet was unplugged; the stroke ended there\n");
  };
  const auto stats = rig::pen::play_pen(audition, pen, o.seconds, {}, events);
  pen.on_sample({});
  nlohmann::json recording = nullptr;
  if (recorder) {
    if (const auto summary = recorder->stop(); summary && summary->kept) {
      say_wrote(summary->file);
      recording = summary->file.string();
    }
  }
  const auto status = pen.status();
  std::printf("pen: %llu strokes, %llu contacts; report interval %.2f ms, speed lag %.2f ms; "
              "report to engine %.2f ms mean, %.2f ms worst\n",
              static_cast<unsigned long long>(stats.strokes), static_cast<unsigned long long>(stats.contacts),
              1e3 * status.report_interval_s, 1e3 * status.lag_s, 1e3 * stats.mean_post_s, 1e3 * stats.max_post_s);
  return {{"tablet", t.name},
          {"pressure_curve",
           curve.is_default ? nlohmann::json(nullptr) : nlohmann::json(curve.file.string())},
          {"stroke_events", strokes},
          {"strokes", stats.strokes},
          {"contacts", stats.contacts},
          {"report_interval_s", status.report_interval_s},
          {"speed_lag_s", status.lag_s},
          {"report_to_engine_mean_s", stats.mean_post_s},
          {"report_to_engine_max_s", stats.max_post_s},
          {"tablet_removed", removed || stats.tablet_removed},
          {"recording", recording}};
}

void audition(const AuditionOptions& o) {
  if (o.also.size() > 2) throw CLI::ValidationError("--also", "takes at most two more tools (a triplet)");
  if (!o.pen.empty() && !o.also.empty()) throw CLI::ValidationError("--also", "plays in turn with a stroke, not with --pen");
  if (o.pen.empty() && !o.record_folder.empty()) throw CLI::ValidationError("--record", "records a pen's strokes: give --pen");
  const playback::OutputSettings device = output_settings(o.device, "nibrig-audition");
  model::design::ToolSounds sounds(tool_sound_options(o.stroke));
  std::vector<std::string> tools{o.stroke.tool};
  tools.insert(tools.end(), o.also.begin(), o.also.end());
  for (const auto& tool : tools) sounds.check(tool, o.stroke.surface);  // before any work
  rt::Stroke stroke = make_stroke(o.stroke);
  rt::EngineSettings settings;
  settings.sample_rate_hz = device.sample_rate;
  settings.slots = tools.size();
  playback::LiveAudition audition(settings);
  std::string modes;
  for (std::size_t i = 0; i < tools.size(); ++i) {
    const model::design::ToolSound sound = sounds.sound(tools[i], o.stroke.surface);
    if (i == 0) modes = sound.modes;
    audition.load(i, sound, o.stroke.seed + i);
  }
  std::unique_ptr<rig::pen::PenStylus> pen;
  if (o.pen.empty()) {
    audition.attach(std::move(stroke.source));
  } else {
    pen = std::make_unique<rig::pen::PenStylus>(o.pen, o.pen_name);
  }
  const std::vector<std::string>& names = audition.names();
  nlohmann::json result{{"tools", tools}, {"surface", o.stroke.surface}, {"modes", modes}};
  result["actuator"] = nullptr;
  if (!o.actuator.empty()) {
    const auto calibration = playback::read_actuator_file(playback::find_actuator(o.actuator));
    const auto filter = audition.use_actuator(calibration, calibration.name);
    std::printf("actuator '%s' (calibrated %s): inverse filter flat to %.2f dB over %.0f-%.0f Hz\n",
                calibration.name.c_str(), calibration.created.c_str(), filter.max_deviation_db,
                calibration.design.band_low_hz, calibration.design.band_high_hz);
    result["actuator"] = {{"name", calibration.name},
                          {"created", calibration.created},
                          {"max_deviation_db", filter.max_deviation_db},
                          {"band_low_hz", calibration.design.band_low_hz},
                          {"band_high_hz", calibration.design.band_high_hz}};
  }
  const double seconds = o.seconds > 0 ? o.seconds : stroke.natural_seconds;

  const double started_s = rig::pen::pen_clock_now_s();
  audition.open(device);
  const auto info = *audition.stream_info();
  std::printf("playing %s through %s on %s '%s' channel %u at %u Hz, %u-frame periods; %s\n",
              names[0].c_str(), modes.c_str(), info.api.c_str(), info.device.c_str(),
              device.output_channel, info.sample_rate, info.period_frames,
              stroke.description.c_str());
  result["stream"] = stream_json(info);
  result["output_channel"] = device.output_channel;
  result["stroke"] = stroke.description;
  result["pen"] = nullptr;
  result["switches"] = nlohmann::json::array();
  result["device_lost_at_s"] = nlohmann::json::array();
  if (pen) {
    result["pen"] = play_with_pen(audition, *pen, o, started_s);
  } else {
    playback::AlternationEvents events;
    events.switched = [&names, &tools, &result](double t, std::size_t slot) {
      std::printf("%6.2f s: now %s\n", t, names[slot].c_str());
      result["switches"].push_back({{"at_s", t}, {"tool", tools[slot]}});
    };
    events.device_lost = [&result](double t, const std::string& problem) {
      std::printf("%6.2f s: device lost (%s); waiting for it to return\n", t, problem.c_str());
      result["device_lost_at_s"].push_back(t);
    };
    playback::play_in_turn(audition, {seconds, o.switch_every}, events);
    const auto e = audition.engine_stats();
    const auto d = *audition.output_stats();
    std::printf(
        "played %.1f s: %llu callbacks; engine overruns %llu; callback median <= %.1f us, 99th "
        "percentile <= %.1f us, max %.1f us; peak %.3f of full scale, %llu samples limited; "
        "device underflows %llu, losses %llu, reconnects %llu\n",
        seconds, static_cast<unsigned long long>(e.callbacks),
        static_cast<unsigned long long>(e.overruns), 1e6 * e.callback_time_quantile(0.5),
        1e6 * e.callback_time_quantile(0.99), 1e6 * e.max_callback_s, e.peak_output,
        static_cast<unsigned long long>(e.limited_samples),
        static_cast<unsigned long long>(d.output_underflows),
        static_cast<unsigned long long>(d.losses), static_cast<unsigned long long>(d.reconnects));
    result["seconds"] = seconds;
  }
  if (o.json.empty()) return;
  result["engine"] = engine_stats_json(audition.engine_stats());
  result["device"] = output_stats_json(*audition.output_stats());
  write_json_numbers(o.json, result);
}

void calibrate(const CalibrateOptions& o) {
  playback::CalibrationRunSettings s;
  s.name = o.name;
  s.device = output_settings(o.device, "nibrig-calibrate");
  s.device.input_channel = o.input_channel;
  s.accelerometer_m_s2_per_unit = o.accelerometer;
  const auto c = playback::run_calibration(s);
  const auto file = o.output.empty() ? playback::actuator_path(o.name) : o.output;
  std::filesystem::create_directories(file.parent_path().empty() ? "." : file.parent_path());
  playback::write_actuator_file(file, c);
  std::printf("actuator '%s': chain delay %.2f ms; inverse filter (%zu taps at %.0f Hz) flat to "
              "%.2f dB over %.0f-%.0f Hz (rms %.2f dB), largest boost %.1f dB%s\n",
              c.name.c_str(), 1e3 * c.delay_s, c.filter.taps.size(), c.filter.sample_rate_hz,
              c.filter.max_deviation_db, c.design.band_low_hz, c.design.band_high_hz, c.filter.rms_deviation_db, c.filter.max_boost_db,
              c.filter.boost_limited.empty() ? "" : " (capped in places: not flattened there)");
  say_wrote(file);
}

}  // namespace

void add_audio_commands(CLI::App& app, std::shared_ptr<const GlobalOptions> global) {
  auto* list = app.add_subcommand("devices", "List audio APIs and devices, and pen tablets (choose them by name)");
  auto devices_json = std::make_shared<std::filesystem::path>();
  add_json_option(list, *devices_json, "the list");
  list->callback([global, devices_json] {
    configure_logging(global->verbosity);
    devices(*devices_json);
  });

  auto a = std::make_shared<AuditionOptions>();
  auto* play = app.add_subcommand(
      "audition", "Play a tool on a surface through the real-time engine on an audio device");
  add_stroke_options(play, a->stroke);
  add_device_options(play, a->device);
  play->add_option("--also", a->also,
                   "One or two more tools on the same surface: the engine switches between them "
                   "(A/B or triplet) every --switch-every seconds");
  play->add_option("--switch-every", a->switch_every, "Seconds between switches")
      ->check(in_range(0.05, 3600, "a time in seconds"));
  play->add_option("--seconds", a->seconds, "How long to play (default: the stroke's length)")
      ->check(in_range(0.001, 86400, "a length in seconds"));
  play->add_option("--actuator", a->actuator,
                   "Actuator calibration from `nibrig calibrate`: its name, or a file");
  play->add_option("--pen", a->pen,
                   "Play from a pen tablet (by part of its name, see `nibrig devices`): the pen's speed and "
                   "force drive the engine; tip down starts a stroke, tip up ends it");
  play->add_option("--pen-name", a->pen_name, "The pen's calibration (`nibrig pen calibrate --name`); default: the tablet's name");
  play->add_option("--record", a->record_folder,
                   "With --pen: record the strokes into this folder, in the paper's drawing format "
                   "(replay with `render --trajectory`)");
  add_json_option(play, a->json,
                  "what was played and measured (switches, engine and device counters, the pen's "
                  "strokes)");
  play->callback([a, global] {
    configure_logging(global->verbosity);
    for (const auto& note : outside_measured_range(a->stroke)) spdlog::warn("{}", note);
    audition(*a);
  });

  auto c = std::make_shared<CalibrateOptions>();
  auto* cal = app.add_subcommand(
      "calibrate", "Measure an actuator with a sweep and its accelerometer; store its inverse filter");
  cal->add_option("--name", c->name, "The actuator's name")->required();
  add_device_options(cal, c->device);
  cal->add_option("--input-channel", c->input_channel,
                  "Input channel of the accelerometer (1-based)")
      ->check(whole_in_range(1, playback::kMostOutputChannels, "a channel number"));
  cal->add_option("--accelerometer", c->accelerometer,
                  "m/s² per unit of input level (accelerometer sensitivity and input gain)")
      ->check(in_range(1e-6, 1e6, "a sensitivity in m/s² per unit of input"));
  cal->add_option("-o,--output", c->output,
                  "Actuator file to write (default: the actuator store, see `nibrig calibrate "
                  "--help`)")
      ->check(file_to_write());
  cal->footer("Calibrations are stored per actuator name in $NIBRIG_ACTUATORS, else\n"
              "$XDG_DATA_HOME/nibrig/actuators, else ~/.local/share/nibrig/actuators;\n"
              "`nibrig audition --actuator NAME` finds them there.");
  cal->callback([c, global] {
    configure_logging(global->verbosity);
    calibrate(*c);
  });
}

}  // namespace nibrig::ui::cli
