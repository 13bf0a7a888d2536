// `nibrig defaults`: what the faces compute on first use from the bundled inputs (the default
// space, the forcing models, the stylus's modes, the design grid), computed now into the user
// cache. The build runs it into its own defaults/ folder (NIBRIG_CACHE pointed there), the layer a
// first start reads. The work is model/design/bundled_defaults.hpp's; this file holds the options
// and the printing.
#include <fmt/format.h>

#include <cstdio>
#include <functional>
#include <memory>

#include "model/design/bundled_defaults.hpp"
#include "model/io/user_cache.hpp"
#include "model/numeric/cancellation.hpp"
#include "ui/cli/app.hpp"
#include "ui/cli/commands.hpp"
#include "ui/cli/interrupt_scope.hpp"
#include "ui/cli/logging.hpp"
#include "ui/cli/output.hpp"
#include "ui/cli/progress.hpp"

namespace nibrig::ui::cli {
namespace {

void compute_defaults(const std::filesystem::path& json, unsigned threads) {
  InterruptScope interrupt;
  model::design::DefaultsOptions options;
  options.threads = threads;
  options.stop = interrupt.token();
  std::string step_shown;
  std::function<void(std::size_t, std::size_t)> bar;
  options.progress = [&](const std::string& step, std::size_t done, std::size_t total) {
    if (step != step_shown) step_shown = step, bar = progress_bar(step);
    if (done > 0 && total > 0) bar(done, total);
  };
  std::vector<model::design::BundledDefault> made;
  try {
    made = model::design::compute_bundled_defaults(options);
  } catch (const model::numeric::Cancelled&) {
    throw Interrupted("stopped; what was complete is kept, nothing half-made");
  }
  nlohmann::json numbers = {{"cache", model::io::user_cache_dir().string()},
                            {"defaults", nlohmann::json::array()}};
  for (const auto& d : made) {
    std::printf("%s: %s in %.1f s, %s\n", d.what.c_str(), d.computed ? "computed" : "read",
                d.seconds, d.file.string().c_str());
    numbers["defaults"].push_back({{"what", d.what},
                                   {"file", d.file.string()},
                                   {"computed", d.computed},
                                   {"seconds", d.seconds}});
  }
  write_json_numbers(json, numbers);
}

}  // namespace

void add_defaults_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global) {
  auto json = std::make_shared<std::filesystem::path>();
  auto* cmd = app.add_subcommand(
      "defaults",
      "Compute what the panel and the commands compute on first use from the bundled inputs");
  cmd->footer(
      "The default space, the default forcing model (at the panel's resolution and at the stylus\n"
      "template's), the bundled stylus's modes and the vero-DM85 design grid, into the user cache\n"
      "($NIBRIG_CACHE, else ~/.cache/nibrig); each one there already is read, not computed. The\n"
      "build runs this into build/<tree>/defaults, which every first start reads beneath the "
      "cache.");
  add_json_option(cmd, *json, "each default's file, whether it was computed and its seconds");
  cmd->callback([json, global] {
    configure_logging(global->verbosity);
    compute_defaults(*json, worker_threads(*global));
  });
}

}  // namespace nibrig::ui::cli
