#include "ui/panel/panel_options.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <vector>

#include "ui/options/number_checks.hpp"
#include "ui/panel/panel_window.hpp"

namespace nibrig::ui::panel {

std::optional<PanelOptions> parse_panel_options(int argc, char** argv, int& exit_code) {
  PanelOptions o;
  std::string view = "space";
  CLI::App app{"nibrig-panel: browse the perceptual space, feel a tool, design one, watch the rig"};
  app.add_option("--catalog", o.setup.catalog, "tool catalog (default: the bundled one)")->check(CLI::ExistingFile);
  app.add_option("--space", o.setup.space,
                 "perceptual space file (default: the demo's, computed on first start and kept)")
      ->check(CLI::ExistingFile);
  app.add_option("--forcing", o.setup.forcing, "forcing model file (default: fitted from the catalog and kept)")
      ->check(CLI::ExistingFile);
  app.add_option("--loop", o.setup.loop,
                 "a design loop's folder, its rounds shown in the design view")
      ->check(CLI::ExistingDirectory);
  app.add_option("--screenshot", o.screenshot, "render one view into this PNG and exit");
  app.add_option("--view", view, "the view shown first (space, design, rig, pad, devices)")
      ->check(CLI::IsMember({"space", "design", "rig", "pad", "devices", "experiment"}));
  app.add_option("--frames", o.frames, "frames drawn before the screenshot, once the view has loaded")
      ->check(whole_in_range(1, 100000, "frames"));
  app.add_option("--settle-timeout", o.settle_timeout_s,
                 "longest wait, in seconds, for the view's background work before the screenshot "
                 "(the design grid is solved the first time: the window shows its progress and the "
                 "time left, measured as it goes); 0: do not wait")
      ->check(in_range(0.0, 86400.0, "seconds"));
  std::vector<long long> grid;
  app.add_option("--design-grid", grid,
                 "designs the design view solves: mix points and tip points (default 5,7); fewer solve "
                 "faster, with a larger interpolation error (the view measures it)")
      ->delimiter(',')
      ->expected(2)
      ->check(whole_in_range(2, 50, "points"));
  app.add_option("--design-mesh", o.setup.design.mesh_size_m,
                 "element size the design view meshes its styli with, in metres (default: the bundled stylus's)")
      ->check(in_range(0.0005, 0.01, "metres"));
  app.add_option("--design-modes", o.setup.design.modes, "modes the design view solves (default: the bundled stylus's)")
      ->check(whole_in_range(4, 256, "modes"));
  app.add_option("--size", o.width, "window width in pixels")
      ->check(whole_in_range(PanelWindow::kMinWidth, 8192, "pixels"));
  app.add_option("--height", o.height, "window height in pixels")
      ->check(whole_in_range(PanelWindow::kMinHeight, 8192, "pixels"));
  app.add_option("--api", o.device_api, "audio API of the actuator (jack, alsa, pulse)");
  app.add_option("--device", o.device, "audio device of the actuator, by name");
  app.add_flag("--start-rig", o.setup.start_rig,
               "start the rig view's live comparison at once (the simulated rig, 8 times real time); a "
               "screenshot of the rig view is then taken half way through");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    exit_code = app.exit(e);
    return std::nullopt;
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "nibrig-panel: error: %s\n", e.what());
    exit_code = 2;
    return std::nullopt;
  }
  o.view = *view_named(view);
  o.view_given = app.count("--view") > 0;
  if (grid.size() == 2) {
    o.setup.design.fraction_points = static_cast<std::size_t>(grid[0]);
    o.setup.design.tip_points = static_cast<std::size_t>(grid[1]);
  }
  if (!o.device_api.empty() || !o.device.empty()) o.setup.device = DeviceRequest{o.device_api, o.device, 1, 256};
  exit_code = 0;
  return o;
}

}  // namespace nibrig::ui::panel
