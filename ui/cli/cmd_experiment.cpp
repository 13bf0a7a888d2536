// `nibrig experiment run` and `nibrig experiment report`: triplet studies (the paper's Sec. 4.2
// and 6.1) with a person at the terminal or a simulated participant, on the actuator or the
// turntable. The study, its order, log, resume and report are model/study; starting a session (the
// checks, the folder, the sounds, the presenter) is rig/study/study_start; this file holds options and
// presentation.
#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <random>
#include <thread>

#include "model/design/design_search.hpp"
#include "model/design/tool_sound.hpp"
#include "model/space/simulated_observer.hpp"
#include "model/space/space_file.hpp"
#include "model/study/simulated_participant.hpp"
#include "model/study/stimulus_list.hpp"
#include "model/study/study_session.hpp"
#include "playback/actuator_store.hpp"
#include "playback/audio_devices.hpp"
#include "playback/live_audition.hpp"
#include "rig/pacer.hpp"
#include "rig/rig_request.hpp"
#include "rig/study/study_rehearsal.hpp"
#include "rig/study/study_start.hpp"
#include "ui/cli/commands.hpp"
#include "ui/cli/experiment_commands.hpp"
#include "ui/cli/experiment_terminal.hpp"
#include "ui/cli/forcing_options.hpp"
#include "ui/cli/logging.hpp"
#include "ui/cli/output.hpp"
#include "ui/cli/progress.hpp"
#include "ui/options/number_checks.hpp"

namespace nibrig::ui::cli {
namespace {

namespace study = model::study;

// The simulated participant in time: each play after the one before by its share of the modelled
// response time, divided by the pace (0: no waiting at all).
// Ten times slower than a person is as slow as anyone watches a simulated participant; a million
// times faster leaves no wait a clock can measure.
constexpr double kSlowestPace = 0.1;
constexpr double kFastestPace = 1e6;

class PacedParticipant final : public study::Respondent {
 public:
  PacedParticipant(study::SimulatedParticipant& inner, double pace) : inner_(inner), pace_(pace) {}
  bool agree(const study::StudyTexts& texts) override { return inner_.agree(texts); }
  study::Answer answer(const study::TrialPrompt& prompt,
                       const std::function<void(study::Role)>& play) override {
    std::vector<study::Role> asked;
    const study::Answer a = inner_.answer(prompt, [&](study::Role r) { asked.push_back(r); });
    const double each = pace_ > 0 ? a.response_s.value_or(0.0) / pace_ / static_cast<double>(asked.size()) : 0.0;
    for (study::Role r : asked) {
      play(r);
      if (each > 0) std::this_thread::sleep_for(std::chrono::duration<double>(each));
    }
    return a;
  }
  void rest(std::size_t done, std::size_t total) override { inner_.rest(done, total); }

 private:
  study::SimulatedParticipant& inner_;
  double pace_;
};

study::StudyDefinition definition_from(const ExperimentRunOptions& o) {
  study::StudyDefinition d;
  d.stimuli = study::read_stimulus_list(o.stimuli);
  d.mode = *study::parse_mode(o.mode);  // checked by the option
  if (const auto plan = study::parse_plan(o.plan); plan && *plan != study::PlanKind::file) {
    d.plan = *plan;
  } else {
    // A trial list made beforehand (`nibrig space plan`), its names the stimuli's.
    std::vector<std::string> names;
    for (const auto& s : d.stimuli) names.push_back(s.name);
    d.plan = study::PlanKind::file;
    d.listed_trials = model::space::read_trial_csv(o.plan, names).trials;
  }
  d.trials = o.trials;
  d.practice = o.practice;
  d.break_every = o.break_every;
  d.dims = o.dims;
  try {
    study::validate(d);
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError("--stimuli", o.stimuli.string() + ": " + e.what());
  }
  return d;
}

// The rig of rig mode, without its tool: the start sets each stimulus's.
rig::RigRequest turntable_request(const ExperimentRunOptions& o) {
  rig::RigRequest r;
  if (o.usb) {
    r.kind = rig::RigKind::usb;
    r.usb_serial = *o.usb;
    r.input_api = o.input_api;
    r.input_device = o.input;
    r.input_channel = o.input_channel;
    r.accelerometer_m_s2_per_full_scale = o.accelerometer;
  } else {
    r.kind = rig::RigKind::simulated;
    // A simulated participant does not wait for the turntable; a person feels it in real time.
    r.speedup = o.rig_speedup.value_or(o.simulate.empty() ? 1.0 : 0.0);
  }
  return r;
}

// A refused start as the option at fault; a stimulus the catalog lacks stays a plain error, as
// any unknown tool is elsewhere.
[[noreturn]] void throw_as_option(const rig::StudyStartRefused& e) {
  using Field = rig::StudyStartRefused::Field;
  switch (e.field()) {
    case Field::participant: throw CLI::ValidationError("--participant", e.what());
    case Field::definition: throw CLI::ValidationError("--stimuli", e.what());
    case Field::folder: throw CLI::ValidationError("-o", e.what());
    case Field::rig:
      throw CLI::ValidationError("--mode",
                                 std::string(e.what()) + ": --simulated-rig or --usb [SERIAL]");
    case Field::stimulus: break;
  }
  throw e;
}

// What the trial count will be, from five simulated participants judging `truth` by `model`.
void say_estimate(const study::StudyDefinition& d, const Eigen::MatrixXd& truth,
                  const model::space::JudgmentModel& model, std::uint64_t seed, unsigned threads,
                  const std::string& whose) {
  const study::TrialEstimate e = study::estimate_trials(d, truth, study::kEstimateRuns, seed, threads, model);
  std::cout << fmt::format(
      "{} stimuli, {} plan, {} mode: about {:.0f} trials with {} practice ({}-{} over {} simulated "
      "participants answering from {})\n",
      d.stimuli.size(), study::plan_name(d.plan), study::mode_name(d.mode), e.mean, d.practice,
      e.least, e.most, e.runs, whose);
}

}  // namespace

void run_experiment(const ExperimentRunOptions& o, unsigned threads) {
  const bool simulated = !o.simulate.empty();
  // 1. The start: the study from the list (or on --resume the folder's own), and the presenters'
  // inputs. The person at the terminal is made once nothing more can be refused.
  rig::StudyStartRequest request;
  if (!o.stimuli.empty()) request.definition = definition_from(o);
  request.settings.study = o.output;
  request.settings.participant = o.participant;
  request.settings.seed = o.seed;
  request.settings.resume = o.resume;
  request.settings.threads = threads;
  request.instructions = o.instructions;
  request.consent = o.consent;
  request.sounds = {o.catalog, o.design, o.forcing_model, design_progress()};
  std::unique_ptr<TerminalParticipant> person;
  std::optional<playback::OutputSettings> device;
  std::unique_ptr<playback::LiveAudition> audition;
  if (!simulated) {
    request.audition = [&o, &device, &audition]() -> playback::LiveAudition& {
      rt::EngineSettings settings;
      settings.sample_rate_hz = device->sample_rate;
      audition = std::make_unique<playback::LiveAudition>(settings);
      audition->open(*device);
      if (!o.actuator.empty()) {
        const auto calibration = playback::read_actuator_file(playback::find_actuator(o.actuator));
        audition->use_actuator(calibration, calibration.name);
      }
      const auto info = *audition->stream_info();
      std::printf("playing on %s '%s' at %u Hz\n", info.api.c_str(), info.device.c_str(),
                  info.sample_rate);
      return *audition;
    };
  }
  if (o.simulated_rig || o.usb) request.rig = [&o] { return turntable_request(o); };
  // A person's operator confirms each mount with Enter; a simulated study only says it.
  request.mount = [&person](const std::string& message) {
    std::printf("operator: %s%s\n", message.c_str(), person ? " (Enter when done)" : "");
    if (person) person->wait_for_enter();
  };
  request.notice = [](const std::string& message) {
    std::printf("operator: %s\n", message.c_str());
  };

  // 2. Everything that can be refused is refused before the participant starts.
  std::optional<rig::StudyStart> start;
  try {
    start.emplace(std::move(request));
  } catch (const rig::StudyStartRefused& e) {
    throw_as_option(e);
  }
  const study::StudyDefinition& definition = start->definition();
  std::unique_ptr<study::SimulatedParticipant> simulated_participant;
  Eigen::MatrixXd truth;
  model::space::JudgmentModel judging;  // the paper's, unless the space judged by another
  if (simulated) {
    rig::Rehearsal rehearsal = rig::rehearse_from(*start, o.simulate, o.lapse_rate, o.seed);
    truth = std::move(rehearsal.truth);
    judging = rehearsal.judging;
    simulated_participant = std::move(rehearsal.participant);
  } else {
    // No space to answer from: the estimate asks observers of a random space of the usual spread.
    truth = study::estimate_space(definition.dims, definition.stimuli.size());
  }
  if (!simulated && definition.mode != study::StudyMode::rig)
    device = output_settings(o.device, "nibrig-experiment");
  say_estimate(definition, truth, judging, o.seed.value_or(1), threads,
               simulated ? o.simulate.string() : "a random space");

  // 3. The study folder, the stimuli's sounds, who answers and what they feel.
  rig::ReadyStudy ready;
  try {
    start->prepare(progress_bar("making the stimuli's sounds"));
    ready = start->ready();
  } catch (const rig::StudyStartRefused& e) {
    throw_as_option(e);
  }
  std::unique_ptr<PacedParticipant> paced;
  study::Respondent* respondent = nullptr;
  if (simulated) {
    paced = std::make_unique<PacedParticipant>(*simulated_participant, o.pace);
    respondent = paced.get();
  } else {
    person = std::make_unique<TerminalParticipant>(STDIN_FILENO, stdout);
    respondent = person.get();
  }

  // 4. The session.
  const auto began = std::chrono::steady_clock::now();
  const study::StudyResult r = study::run_study(*ready.session, *respondent);
  for (const auto& w : r.warnings) spdlog::warn("{}", w);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  if (r.declined) {
    std::cout << "the participant declined: nothing was recorded\n";
    return;
  }
  std::cout << fmt::format("participant {}: {} trials answered in {:.1f} s{}\n", o.participant,
                           r.answered, seconds,
                           r.resumed_at ? fmt::format(", after {} before", r.resumed_at) : "");
  say_wrote(study::participant_folder(o.output, o.participant) / study::kResponsesFile);
  if (r.complete)
    std::cout << "the participant's part of the study is complete; `nibrig experiment report "
              << o.output.string() << "` fits the space\n";
  else
    std::cout << "stopped before the end; continue with `nibrig experiment run -o "
              << o.output.string() << " --participant " << o.participant << " --resume`\n";
}

void add_experiment_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global) {
  auto* cmd = app.add_subcommand("experiment", "Triplet studies with people: run one, report it");
  cmd->require_subcommand(1);

  auto o = std::make_shared<ExperimentRunOptions>();
  auto* run = cmd->add_subcommand("run", "Run (or resume) one participant's session of a study");
  run->footer(
      "A study lives in its folder (-o): study.json, the instructions and consent texts (edit them\n"
      "there), and per participant the answers, appended and flushed to disk as each is given.\n"
      "More participants join with the same stimuli and folder; `experiment report` merges them.\n"
      "At a terminal: r, a, b play the reference, A and B; 1 or 2 answers; q stops (--resume).");
  run->add_option("--stimuli", o->stimuli,
                  "Stimulus list: one tool/surface or design-point/surface a line, or NAME = ... "
                  "(a new study needs it)")
      ->check(CLI::ExistingFile);
  run->add_option("--mode", o->mode, "actuator (default), rig or validation (Sec. 6.1: designs "
                                     "against the first stimulus)")
      ->check(CLI::IsMember({"actuator", "rig", "validation"}));
  run->add_option("--participant", o->participant, "Participant ID (names their folder)")->required();
  run->add_option("--simulate", o->simulate,
                  "A space (space.json): a simulated participant answers from it, judging by the "
                  "space's judgment model; nothing is played and no device is needed")
      ->check(CLI::ExistingFile);
  run->add_option("--lapse-rate", o->lapse_rate,
                  "With --simulate: a share of answers given at random besides the space model's "
                  "own lapse (default 0)")
      ->check(in_range(0, 1, "a share of answers"));
  run->add_option("--pace", o->pace,
                  "With --simulate: take its modelled response times divided by this (1: as a "
                  "person; default 0: no waiting)")
      ->check(off_or_in_range(kSlowestPace, kFastestPace, "a speed factor"));
  run->add_option_function<std::uint64_t>(
         "--seed", [o](const std::uint64_t& s) { o->seed = s; },
         "Seed of the participant's trial order (default: from the participant ID)")
      ->check(any_seed());
  run->add_option("--plan", o->plan,
                  "two-stage (the paper's, default), adaptive (expected information gain), or a "
                  "trial list from `space plan`");
  run->add_option("--trials", o->trials,
                  "Main trials (default: the plan's own: two-stage the paper's sizes)")
      ->check(whole_in_range(1, 1000000, "a number of trials"));
  run->add_option("--practice", o->practice, "Practice trials first, never fitted (default 3)")
      ->check(whole_in_range(0, 100, "a number of trials"));
  run->add_option("--break-every", o->break_every, "A rest after this many trials (default 100; 0: none)")
      ->check(whole_in_range(0, 1000000, "a number of trials"));
  run->add_option("--dims", o->dims, "Dimensions of the adaptive plan's space (default 2)")
      ->check(whole_in_range(1, 10, "a number of dimensions"));
  run->add_flag("--resume", o->resume, "Continue the participant's session where it stopped");
  run->add_flag("--simulated-rig", o->simulated_rig, "Rig mode: the simulated rig, each stimulus simulated");
  run->add_option_function<double>(
         "--rig-speedup", [o](const double& k) { o->rig_speedup = k; },
         "Simulated rig: 1 = real time, k = k times faster, 0 = as fast as it computes (default: "
         "1, and 0 with --simulate)")
      ->check(off_or_in_range(rig::Pacer::kMinSpeedup, rig::Pacer::kMaxSpeedup,
                              "a speed-up factor"));
  run->add_option_function<std::string>(
         "--usb", [o](const std::string& serial) { o->usb = serial; },
         "Rig mode: the USB rig controller (by serial; alone: the only one)")
      ->expected(0, 1);
  run->add_option("--input", o->input, "USB rig: the accelerometer's audio input (by name)");
  run->add_option("--input-api", o->input_api, "USB rig: the audio back end of --input");
  run->add_option("--input-channel", o->input_channel, "USB rig: the accelerometer's input channel")
      ->check(whole_in_range(1, playback::kMostOutputChannels, "a channel number"));
  run->add_option("--accelerometer", o->accelerometer, "USB rig: the accelerometer's m/s² at full scale")
      ->check(in_range(0.01, 1e6, "m/s² per full scale"));
  run->add_option("--instructions", o->instructions, "Instructions text for a new study (default: bundled)")
      ->check(CLI::ExistingFile);
  run->add_option("--consent", o->consent, "Consent text for a new study (default: bundled)")
      ->check(CLI::ExistingFile);
  run->add_option("--catalog", o->catalog, "Catalog JSON (default: the bundled one)");
  run->add_option("--design", o->design, "Stylus design whose modes shape catalog tools");
  run->add_option("--forcing", o->forcing_model, "Forcing model for design points");
  add_device_options(run, o->device);
  run->add_option("--actuator", o->actuator, "Actuator calibration from `nibrig calibrate`");
  run->add_option("-o,--output", o->output, "The study folder")->required();
  run->callback([o, global] {
    configure_logging(global->verbosity);
    run_experiment(*o, worker_threads(*global));
  });

  auto r = std::make_shared<ExperimentReportOptions>();
  auto* report = cmd->add_subcommand("report", "Merge a study's participants, fit the space, report");
  report->footer(
      "Writes judgments.csv (what `space fit` reads), space.json with bootstrap regions (not for a\n"
      "validation study), report.json and figures. Agreement: each answer against the space's\n"
      "prediction and against the other participants' majority; a validation study gives the\n"
      "statistics of Sec. 6.1 against --space.");
  report->add_option("study", r->study, "The study folder")->required()->check(CLI::ExistingDirectory);
  report->add_option("-o,--output", r->output, "Report folder (default: STUDY/report)");
  report->add_option("--space", r->space, "Validation study: the space it tests")->check(CLI::ExistingFile);
  report->add_option("--catalog", r->catalog, "Catalog JSON (default: the bundled one)");
  report->add_flag("--all-judgments", r->all_judgments,
                   "Fit every answer (default for two-stage: the paper's selection)");
  report->add_option("--bootstrap", r->bootstrap, "Resamples for the regions (default 200; 0: none)")
      ->check(whole_in_range(0, 100000, "a number of resamples"));
  report->add_option("--starts", r->starts, "Random starts of the fit (default 16)")
      ->check(whole_in_range(1, 10000, "a number of starts"));
  report->add_option("--seed", r->seed, "Seed of the fit (default 1)")->check(any_seed());
  report->callback([r, global] {
    configure_logging(global->verbosity);
    if (r->bootstrap == 1) throw CLI::ValidationError("--bootstrap", "needs at least 2 resamples");
    run_experiment_report(*r, worker_threads(*global));
  });
}

}  // namespace nibrig::ui::cli
