// `nibrig design loop`: from a print back to its target. Each round proposes a design and writes
// its print's files, has the print measured on the rig (inside the loop with --simulated or --usb,
// else by the lab with `nibrig rig capture`, then --resume), takes the measurement in and proposes
// the next, until a print is within the target's threshold. The session is
// model/design/loop_session.hpp and the rig's part rig/loop_print_capture.hpp; this file holds
// options and presentation.
#include <fmt/format.h>

#include <cstdio>
#include <functional>
#include <optional>
#include <string>

#include "model/design/loop_session.hpp"
#include "model/numeric/cancellation.hpp"
#include "playback/audio_devices.hpp"
#include "rig/accelerometer_input.hpp"
#include "rig/loop_print_capture.hpp"
#include "rig/pacer.hpp"
#include "rig/rig_request.hpp"
#include "rig/speed_profile.hpp"
#include "rt/reference_load.hpp"
#include "ui/cli/app.hpp"
#include "ui/cli/commands.hpp"
#include "ui/cli/forcing_options.hpp"
#include "ui/cli/interrupt_scope.hpp"
#include "ui/cli/logging.hpp"
#include "ui/cli/output.hpp"
#include "ui/cli/progress.hpp"
#include "ui/cli/stylus_report.hpp"
#include "ui/options/number_checks.hpp"

namespace nibrig::ui::cli {

namespace {

namespace design = model::design;

struct LoopOptions {
  std::string target, surface;
  std::filesystem::path space_file, catalog;
  std::string forcing, printer, mix = "vero,DM85",
                                rule = design::rule_name(design::kDefaultNextPrintRule);
  int rounds = design::kDefaultLoopRounds;
  bool rounds_given = false;  // on --resume: the loop's limit changed
  std::filesystem::path output;
  bool resume = false;
  bool simulated = false;
  std::optional<std::string> usb;
  std::filesystem::path replay_prints;
  std::filesystem::path simulated_forcing;
  unsigned seed = 1;
  double speedup = 0.0;
  std::string profile = "steps";
  std::optional<double> seconds;
  double load = rt::kReferenceNormalForce;
  std::string input_api, input;
  unsigned input_channel = 1;
  double accelerometer = rig::kDefaultAccelerometerM_s2;
};

design::LoopRequest loop_request(const LoopOptions& o) {
  design::LoopRequest r;
  r.target = o.target;
  r.surface = o.surface;
  r.space_file = o.space_file;
  r.catalog_file = o.catalog;
  r.forcing = o.forcing;
  r.printer = o.printer;
  const auto comma = o.mix.find(',');
  if (comma == std::string::npos)
    throw CLI::ValidationError("--mix", "takes two materials, e.g. vero,DM85");
  r.first_material = design::catalog_material_name(o.mix.substr(0, comma));
  r.second_material = design::catalog_material_name(o.mix.substr(comma + 1));
  try {
    r.rule = design::parse_next_print_rule(o.rule);
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError("--rule", e.what());
  }
  r.max_rounds = o.rounds;
  // The library's check, as a usage error: a new loop's --target, --surface, --space.
  try {
    design::check_loop_request(r);
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError("design loop", std::string(e.what()) + " (or give --resume)");
  }
  return r;
}

std::optional<rig::LoopCaptureOptions> capture_options(const LoopOptions& o,
                                                       const design::LoopRequest& loop) {
  if (!o.replay_prints.empty()) {
    auto c = rig::replay_recorded_prints(o.replay_prints, loop, o.speedup);
    c.seconds = o.seconds;
    return c;
  }
  if (!o.simulated && !o.usb) return std::nullopt;
  rig::LoopCaptureOptions c;
  c.rig.kind = o.usb ? rig::RigKind::usb : rig::RigKind::simulated;
  if (o.usb) c.rig.usb_serial = *o.usb;
  c.rig.seed = o.seed;
  c.rig.speedup = o.speedup;
  c.rig.load_N = o.load;
  c.rig.input_api = o.input_api;
  c.rig.input_device = o.input;
  c.rig.input_channel = o.input_channel;
  c.rig.accelerometer_m_s2_per_full_scale = o.accelerometer;
  c.sounds.catalog = o.catalog;
  c.sounds.forcing_model = o.simulated_forcing;
  c.sounds.progress = design_progress();
  c.profile = o.profile;
  c.seconds = o.seconds;
  return c;
}

void print_proposed(const design::LoopSession& s, int round) {
  const auto& r = s.rounds().at(static_cast<std::size_t>(round - 1));
  std::printf(
      "round %d: print %s: predicted distance %.3f ± %.3f, chance within the threshold %.0f %%\n",
      round, design::label(r.design).c_str(), r.predicted_distance, r.predicted_distance_sd,
      100 * r.chance_within);
  say_wrote(design::round_print_file(s.folder(), round).parent_path());
}

void print_measured(const design::LoopSession& s, int round) {
  const auto& r = s.rounds().at(static_cast<std::size_t>(round - 1));
  std::printf("round %d: measured distance %.3f ± %.3f (predicted %.3f)%s\n", round,
              r.measured->distance, r.measured->distance_sd, r.predicted_distance,
              r.measured->distance <= s.threshold() ? ": within the threshold" : "");
}

void print_waiting(const design::LoopSession& s, int round) {
  const auto& r = s.rounds().at(static_cast<std::size_t>(round - 1));
  const auto session = design::round_session_folder(s.folder(), round);
  std::printf(
      "round %d waits for its print's measurement: print %s, mount it on %s and run\n"
      "  nibrig rig capture --usb --tool '%s' --surface %s -o %s\n"
      "then: nibrig design loop --resume -o %s\n",
      round, design::round_print_file(s.folder(), round).string().c_str(),
      s.request().surface.c_str(), design::to_string(r.design).c_str(), s.request().surface.c_str(),
      session.string().c_str(), s.folder().string().c_str());
}

void print_rounds(const design::LoopSession& s) {
  std::printf("%-6s %-32s %-18s %-18s\n", "round", "design", "predicted", "measured");
  for (const auto& r : s.rounds())
    std::printf(
        "%-6d %-32s %-18s %-18s\n", r.number, design::label(r.design).c_str(),
        fmt::format("{:.3f} ± {:.3f}", r.predicted_distance, r.predicted_distance_sd).c_str(),
        r.measured
            ? fmt::format("{:.3f} ± {:.3f}", r.measured->distance, r.measured->distance_sd).c_str()
            : "not yet");
}

void run_loop(const LoopOptions& o) {
  std::optional<design::LoopRequest> request;
  std::optional<rig::LoopCaptureOptions> capture;
  if (!o.resume) {
    request = loop_request(o);
    capture = capture_options(o, *request);
    // Replayed prints are the only ones the loop can measure: it proposes nothing else.
    if (capture && !capture->recorded_prints.empty())
      request->candidates = rig::designs_of(capture->recorded_prints);
  }
  std::string step_shown;
  std::function<void(std::size_t, std::size_t)> bar;
  const model::numeric::StepProgress shown = [&](const std::string& step, std::size_t done,
                                                 std::size_t total) {
    if (step != step_shown) step_shown = step, bar = progress_bar(step);
    if (done > 0 && total > 0) bar(done, total);
  };
  auto session = o.resume && o.rounds_given
                     ? design::LoopSession::resume_with_rounds(o.output, o.rounds, shown)
                     : design::LoopSession::open(o.output, request, shown);
  const auto& r = session->request();
  if (o.resume) capture = capture_options(o, r);
  std::printf(
      "target %s, stylus for %s over %s-%s x tips; threshold %.3f (the space's just-noticeable "
      "distance); rule: %s; at most %d rounds\n",
      r.target.c_str(), r.surface.c_str(), r.first_material.c_str(), r.second_material.c_str(),
      session->threshold(), design::rule_name(r.rule).c_str(), r.max_rounds);
  InterruptScope interrupts;
  if (capture) capture->cancel = interrupts.token();
  try {
    rig::drive_design_loop(
        *session, capture,
        [&](rig::LoopStep step, int round) {
          switch (step) {
            case rig::LoopStep::proposed:
              print_proposed(*session, round);
              break;
            case rig::LoopStep::measured:
              print_measured(*session, round);
              break;
            case rig::LoopStep::waiting:
              print_waiting(*session, round);
              break;
            case rig::LoopStep::stopped:
              std::printf("the loop stopped: %s\n", design::describe(session->stopped()).c_str());
              break;
          }
          std::fflush(stdout);
        },
        interrupts.token());
  } catch (const model::numeric::Cancelled&) {
    throw Interrupted("the loop was stopped; resume it with --resume");
  }
  print_rounds(*session);
}

}  // namespace

void add_design_loop_command(CLI::App* design_cmd, std::shared_ptr<const GlobalOptions> global) {
  auto o = std::make_shared<LoopOptions>();
  auto* cmd = design_cmd->add_subcommand(
      "loop", "From a print back to its target: propose, print, measure on the rig, refit, again");
  cmd->footer(
      "Each round proposes a design and writes its print's files into LOOP/round-N/print/. The\n"
      "print is measured on the rig: inside the loop with --simulated or --usb, else by you with\n"
      "`nibrig rig capture ... -o LOOP/round-N/session` and then --resume. Its measurement refits "
      "the\n"
      "forcing model and corrects the predictions near it; the loop stops when a print is within\n"
      "the space's just-noticeable distance of the target, when no design is predicted closer "
      "than\n"
      "the nearest print, or at --rounds. --rule likeliest (the default) prints the design "
      "likeliest\n"
      "to land within that distance; optimum, the predicted optimum. --replay-prints FOLDER\n"
      "stands the paper's recorded prints in for printing (e.g. ../shared/data/piovarci2018): the\n"
      "loop proposes only those, and replays each one's vibration and friction recordings.");
  cmd->add_option("--target", o->target, "Target tool as tool/surface (e.g. cryon/office)");
  cmd->add_option("--surface", o->surface, "Surface the stylus is for (glass, protector, ...)");
  cmd->add_option("--space", o->space_file, "Fitted space with a descriptor map (space fit)");
  cmd->add_option("-o,--output", o->output, "The loop's folder (new, or the one to --resume)")
      ->required();
  cmd->add_flag("--resume", o->resume,
                "Go on with the loop in -o: measure what awaits, then the next round");
  cmd->add_option("--printer", o->printer, printer_option_help());
  cmd->add_option("--mix", o->mix, "The two materials of the designs")->capture_default_str();
  cmd->add_option("--rule", o->rule, "Which design next: likeliest or optimum")
      ->capture_default_str();
  cmd->add_option("--rounds", o->rounds,
                  "The most rounds (with --resume: the loop's new limit; one stopped at its old "
                  "limit goes on)")
      ->capture_default_str()
      ->check(whole_in_range(1, design::kMostLoopRounds, "a number of rounds"));
  cmd->add_option("--catalog", o->catalog, "Tool catalog JSON (default: the bundled one)");
  cmd->add_option("--forcing", o->forcing,
                  "Forcing model to start from (default: the catalog's, cached)");
  auto* simulated =
      cmd->add_flag("--simulated", o->simulated, "Measure each print on the simulated rig");
  auto* usb =
      cmd->add_option_function<std::string>(
             "--usb", [o](const std::string& serial) { o->usb = serial; },
             "Measure each print on the USB rig controller (by serial; alone: the only one)")
          ->expected(0, 1);
  auto* replay = cmd->add_option("--replay-prints", o->replay_prints,
                                 "Measure each print by replaying its recordings found in this "
                                 "folder (the paper's: vibration and friction); the loop proposes "
                                 "only the prints recorded");
  simulated->excludes(usb)->excludes(replay);
  usb->excludes(replay);
  cmd->add_option("--simulated-forcing", o->simulated_forcing,
                  "The forcing model the simulated rig's prints play (default: the loop's own)")
      ->needs(simulated);
  cmd->add_option("--seed", o->seed, "Seed of the simulated rig's noise")->check(any_seed());
  cmd->add_option("--speedup", o->speedup,
                  "Simulated and replayed prints: 1 = real time, k = k times faster, 0 = as fast "
                  "as it computes")
      ->capture_default_str()
      ->check(
          off_or_in_range(rig::Pacer::kMinSpeedup, rig::Pacer::kMaxSpeedup, "a speed-up factor"));
  cmd->add_option("--profile", o->profile, "The rig's speed profile (as rig capture)")
      ->capture_default_str()
      ->excludes(replay);
  cmd->add_option_function<double>(
         "--seconds", [o](const double& s) { o->seconds = s; },
         "Length of each capture (default: the profile's)")
      ->check(
          in_range(rig::kShortestCaptureSeconds, rig::kMaxProfileSeconds, "a length in seconds"));
  cmd->add_option("--load", o->load, "The arm's normal load in N")
      ->check(in_range(rig::kLightestLoadN, rig::kHeaviestLoadN, "a load in N"));
  cmd->add_option("--input", o->input, "USB rig: the accelerometer's audio input (by name)");
  cmd->add_option("--input-api", o->input_api, "USB rig: the audio back end of --input");
  cmd->add_option("--input-channel", o->input_channel, "USB rig: the accelerometer's input channel")
      ->check(whole_in_range(1, playback::kMostOutputChannels, "a channel number"));
  cmd->add_option("--accelerometer", o->accelerometer,
                  "USB rig: the accelerometer's m/s² at full scale")
      ->check(in_range(rig::kLeastAccelerometerM_s2, rig::kMostAccelerometerM_s2,
                       "m/s² per full scale"));
  cmd->callback([o, global, cmd] {
    configure_logging(global->verbosity);
    // A resumed loop is the one its loop.json describes: an option that would change it is refused.
    if (o->resume)
      for (const char* name : {"--target", "--surface", "--space", "--printer", "--mix", "--rule",
                               "--catalog", "--forcing"})
        if (cmd->count(name) > 0)
          throw CLI::ValidationError(
              name, "the resumed loop keeps what its loop.json says; --resume takes only --rounds");
    o->rounds_given = cmd->count("--rounds") > 0;
    run_loop(*o);
  });
}

}  // namespace nibrig::ui::cli
