#include "ui/panel/panel_options.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>

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
  app.add_option("--screenshot", o.screenshot, "render one view into this PNG and exit");
  app.add_option("--view", view, "the view shown first (space, design, rig, pad, devices)")
      ->check(CLI::IsMember({"space", "design", "rig", "pad", "devices"}));
  app.add_option("--frames", o.frames, "frames drawn before the screenshot, once the view has loaded")
      ->check(CLI::Range(1, 100000));
  app.add_option("--size", o.width, "window width in pixels")->check(CLI::Range(320, 8192));
  app.add_option("--height", o.height, "window height in pixels")->check(CLI::Range(240, 8192));
  app.add_option("--api", o.device_api, "audio API of the actuator (jack, alsa, pulse)");
  app.add_option("--device", o.device, "audio device of the actuator, by name");
  app.add_flag("--start-rig", o.start_rig,
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
  o.setup.start_rig = o.start_rig;
  if (!o.device_api.empty() || !o.device.empty()) o.setup.device = DeviceRequest{o.device_api, o.device, 1, 256};
  exit_code = 0;
  return o;
}

}  // namespace nibrig::ui::panel
