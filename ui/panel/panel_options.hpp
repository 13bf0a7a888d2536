// nibrig-panel's command line: which files to open and, for tests and the README's pictures, one
// view rendered after some frames into a PNG. Numbers and names are checked here, before a window
// opens, with a message naming the option.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "ui/panel/panel.hpp"

namespace nibrig::ui::panel {

struct PanelOptions {
  PanelSetup setup;
  std::filesystem::path screenshot;  // non-empty: render, write, exit
  View view = View::space;
  bool view_given = false;  // --view was on the command line (else the remembered view)
  int frames = 10;          // frames drawn (after the view settled) before the screenshot
  double settle_timeout_s = 900.0;  // longest wait for the view's background work
  int width = 1280, height = 800;
  std::string device_api, device;  // opened at start when either is given
};

// Parses argv; on --help prints and returns nullopt with exit_code 0; on a usage error prints
// "nibrig-panel: error: ..." and returns nullopt with exit_code 2.
std::optional<PanelOptions> parse_panel_options(int argc, char** argv, int& exit_code);

}  // namespace nibrig::ui::panel
