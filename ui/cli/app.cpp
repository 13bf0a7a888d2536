#include "ui/cli/app.hpp"

#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <thread>

#include "model/io/interrupt_cleanup.hpp"
#include "model/io/job_files.hpp"
#include "ui/cli/commands.hpp"
#include "ui/cli/logging.hpp"
#include "ui/options/number_checks.hpp"
#include "ui/cli/output.hpp"
#include "ui/cli/usage_errors.hpp"

namespace nibrig::ui::cli {

unsigned worker_threads(const GlobalOptions& global) {
  if (global.threads > 0) return global.threads;
  return std::max(1u, std::thread::hardware_concurrency());
}

namespace {

// -v, -q and -j mean the same before or after the command (`nibrig devices -q`): every app in
// the tree gets the three options, all writing the one GlobalOptions the commands read when they
// run. CLI11's fallthrough() would do it with less code, but it also hands a misspelt subcommand
// to the root, where the "did you mean" hint (usage_errors.cpp) no longer finds it.
void add_global_options(CLI::App& app, const std::shared_ptr<GlobalOptions>& global) {
  auto* verbose = app.add_flag_function(
                         "-v,--verbose",
                         [global](std::int64_t times) {
                           global->verbosity = std::max(global->verbosity, 0) +
                                               static_cast<int>(times);
                         },
                         "More log output on stderr (-v info, -vv debug)")
                      ->group("Global options");
  app.add_flag_callback("-q,--quiet", [global] { global->verbosity = kQuiet; },
                        "Errors only on stderr: no warnings, no progress")
      ->excludes(verbose)
      ->group("Global options");
  app.add_option("-j,--threads", global->threads, "Worker threads (default: one per core)")
      ->check(whole_in_range(1, 256, "a number of threads"))
      ->group("Global options");
  for (CLI::App* sub : app.get_subcommands({})) add_global_options(*sub, global);
}

// Before any command runs: no output may be one of its own inputs.
void check_outputs_before_running(CLI::App& app) {
  for (CLI::App* sub : app.get_subcommands({})) {
    sub->parse_complete_callback([sub] { refuse_outputs_that_are_inputs(*sub); });
    check_outputs_before_running(*sub);
  }
}

}  // namespace

int run(int argc, char** argv) {
  auto global = std::make_shared<GlobalOptions>();
  CLI::App app{
      "nibrig: styli that feel like real drawing tools (Piovarci et al., SIGGRAPH 2018, extended).\n"
      "Measures tools on surfaces into catalogs; auditions a simulated tool on an actuator; runs\n"
      "the live comparison on the turntable rig; fits the perceptual space, predicts printed\n"
      "styli and searches for a design; runs triplet studies with people."};
  app.set_version_flag("--version", std::string("nibrig ") + NIBRIG_VERSION);
  app.require_subcommand(1);
  app.parse_complete_callback([global] { configure_logging(global->verbosity); });

  add_measure_command(app, global);
  add_catalog_command(app, global);
  add_mechanics_command(app, global);
  add_space_command(app, global);
  add_forcing_command(app, global);
  add_predict_command(app, global);
  add_design_command(app, global);
  add_export_command(app, global);
  add_material_command(app, global);
  add_render_command(app, global);
  add_audio_commands(app, global);
  add_pen_command(app, global);
  add_latency_command(app, global);
  add_rig_command(app, global);
  add_experiment_command(app, global);
  add_demo_command(app, global);
  add_defaults_command(app, global);
  add_docs_command(app, global);
  add_global_options(app, global);
  check_outputs_before_running(app);

  // One command is one job: no file it writes may replace one it read, and Ctrl-C leaves no
  // temporary file behind.
  const model::io::JobFiles job;
  model::io::remove_temporaries_on_signals();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return report_parse_error(app, e);
  } catch (const Interrupted& e) {
    std::fprintf(stderr, "nibrig: interrupted: %s\n", e.what());
    return kInterruptedExitCode;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "nibrig: error: %s\n", e.what());
    return 1;
  }
  return 0;
}

}  // namespace nibrig::ui::cli
