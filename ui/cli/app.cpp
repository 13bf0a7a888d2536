#include "ui/cli/app.hpp"

#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <thread>

#include "ui/cli/commands.hpp"
#include "ui/cli/logging.hpp"
#include "ui/cli/number_checks.hpp"
#include "ui/cli/usage_errors.hpp"

namespace nibrig::ui::cli {

unsigned worker_threads(const GlobalOptions& global) {
  if (global.threads > 0) return global.threads;
  return std::max(1u, std::thread::hardware_concurrency());
}

int run(int argc, char** argv) {
  auto global = std::make_shared<GlobalOptions>();
  CLI::App app{
      "nibrig: perception-aware modelling of digital drawing tools.\n"
      "Measures tools on surfaces (friction, vibration spectra), builds tool catalogs of physical\n"
      "descriptors, and reports them. Implements Piovarci et al., SIGGRAPH 2018."};
  app.set_version_flag("--version", "nibrig 0.1.0");
  app.require_subcommand(1);
  auto* verbose =
      app.add_flag("-v,--verbose", global->verbosity, "More log output on stderr (-v info, -vv debug)");
  app.add_flag_callback("-q,--quiet", [global] { global->verbosity = kQuiet; },
                        "Errors only on stderr: no warnings, no progress")
      ->excludes(verbose);
  app.add_option("-j,--threads", global->threads, "Worker threads (default: one per core)")
      ->check(whole_in_range(1, 256, "a number of threads"));
  app.parse_complete_callback([global] { configure_logging(global->verbosity); });

  add_measure_command(app, global);
  add_catalog_command(app, global);
  add_mechanics_command(app, global);
  add_space_command(app, global);
  add_forcing_command(app, global);
  add_predict_command(app, global);
  add_design_command(app, global);
  add_render_command(app, global);
  add_audio_commands(app, global);
  add_demo_command(app, global);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return report_parse_error(app, e);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "nibrig: error: %s\n", e.what());
    return 1;
  }
  return 0;
}

}  // namespace nibrig::ui::cli
