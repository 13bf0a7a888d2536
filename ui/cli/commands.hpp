// The subcommands of `nibrig`, one file each. Every command registers itself on the CLI11 app; its
// callback does the work and throws on failure (app.cpp turns that into one line on stderr).
#pragma once

#include <CLI/CLI.hpp>
#include <memory>

namespace nibrig::ui::cli {

struct GlobalOptions {
  int verbosity = 0;
  unsigned threads = 0;  // 0 = one per core
};

void add_measure_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global);
void add_catalog_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global);
void add_mechanics_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global);
void add_space_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global);
void add_forcing_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global);
// `forcing holdout`, registered by add_forcing_command on its `forcing` subcommand.
void add_forcing_holdout_command(CLI::App* forcing, std::shared_ptr<const GlobalOptions> global);
// `forcing calibrate-material` and `calibrate-surface`, registered on `forcing` too.
void add_forcing_calibrate_commands(CLI::App* forcing, std::shared_ptr<const GlobalOptions> global);
void add_predict_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global);
void add_design_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global);
// `design loop`, under `design`.
void add_design_loop_command(CLI::App* design, std::shared_ptr<const GlobalOptions> global);
// `export`: a design's stylus as 3MF and STL files.
void add_export_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global);
void add_render_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global);
void add_audio_commands(CLI::App& app, std::shared_ptr<const GlobalOptions> global);
// `pen calibrate`: a pen's pressure curve, stored by name.
void add_pen_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global);
void add_latency_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global);
void add_rig_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global);
// `rig calibrate` and `rig flash`, registered by add_rig_command on its `rig` subcommand.
void add_rig_setup_commands(CLI::App* rig, std::shared_ptr<const GlobalOptions> global);
// `rig parts`: the rig's printed parts as files a printer takes, registered on `rig` too.
void add_rig_parts_command(CLI::App* rig, std::shared_ptr<const GlobalOptions> global);
// `material calibrate bar|ringdown` and `material list`: a lab's materials calibrated from prints.
void add_material_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global);
void add_experiment_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global);
void add_demo_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global);
// `defaults`: the bundled defaults computed into the user cache (the build runs it).
void add_defaults_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global);
// `docs` (hidden): the manual pages and bash completion, written from the command line itself.
void add_docs_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global);

// Threads to use for parallel work: the --threads option, or the number of cores.
unsigned worker_threads(const GlobalOptions& global);

}  // namespace nibrig::ui::cli
