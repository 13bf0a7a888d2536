#include "ui/cli/forcing_options.hpp"

#include <CLI/CLI.hpp>
#include <memory>

#include "ui/options/number_checks.hpp"
#include "ui/cli/progress.hpp"

namespace nibrig::ui::cli {

model::forcing::DesignProgress design_progress() {
  // Shared by the copies of the callback; the bar appears with the first design and is drawn to
  // its end by the last.
  auto bar = std::make_shared<std::unique_ptr<Progress>>();
  return [bar](const model::forcing::DesignResponse& r, std::size_t done, std::size_t total) {
    if (!*bar) *bar = std::make_unique<Progress>("simulating designs", total);
    (*bar)->advance(r.design);
    if (done == total) bar->reset();
  };
}

void add_forcing_input_options(CLI::App* cmd, ForcingInputOptions& o) {
  // Files are checked when read, so that a bad one is reported in one line like every other error.
  cmd->add_option("catalog", o.catalog, "Tool catalog JSON (default: the bundled one)");
  cmd->add_option("--design", o.design_template,
                  "Stylus design every printed tool is derived from (default: "
                  "assets/designs/stylus_vero_tip2mm.json)");
  cmd->add_option("--materials", o.materials, "Material table (default: assets/materials.json)");
  cmd->add_option("--modes", o.modes, "Modes per design (default: the template's)")
      ->check(whole_in_range(1, model::forcing::kMostModes, "a number of modes"));
  cmd->add_option("--mesh-size", o.mesh_size, "Element size in metres (default: the template's)")
      ->check(stylus_metres("an element size"));
}

}  // namespace nibrig::ui::cli
