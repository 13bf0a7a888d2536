// nibrig-panel: the window. Everything it shows is in the nibrig_panel library (ui/panel/panel.hpp);
// this file opens the window and runs the frame loop, or renders one view into a PNG.
#include <chrono>
#include <cstdio>
#include <exception>
#include <thread>

#include "ui/panel/devices_view.hpp"
#include "ui/panel/frame_pacing.hpp"
#include "ui/panel/panel.hpp"
#include "ui/panel/panel_options.hpp"
#include "ui/panel/panel_settings.hpp"
#include "ui/panel/panel_window.hpp"
#include "ui/panel/rig_view.hpp"

namespace {

using namespace nibrig::ui::panel;

// A picture of one view, taken once what it shows has loaded (or the timeout), after the frames
// asked for.
int screenshot(PanelWindow& window, Panel& panel, const PanelOptions& options) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(options.settle_timeout_s);
  int settled_frames = 0;
  while (settled_frames < options.frames) {
    window.begin_frame();
    panel.draw();
    const bool settled = panel.settled() || std::chrono::steady_clock::now() > deadline;
    const bool last = settled && settled_frames + 1 == options.frames;
    window.end_frame(last ? options.screenshot : std::filesystem::path());
    if (settled) ++settled_frames;
    else std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  std::printf("wrote %s\n", options.screenshot.c_str());
  return 0;
}

// The interactive panel: what it remembers comes back, the command line first, and is kept on exit.
int interactive(PanelWindow& window, PanelOptions options) {
  const auto file = panel_settings_file();
  PanelSettings remembered;
  std::string problem;
  try {
    remembered = read_panel_settings(file);
  } catch (const std::exception& e) {
    problem = e.what();
  }
  if (options.setup.space.empty() && !remembered.space.empty() && std::filesystem::exists(remembered.space))
    options.setup.space = remembered.space;
  if (!options.setup.device) options.setup.device = remembered.device;
  Panel panel(options.setup);
  if (!problem.empty()) panel.set_error(problem);
  if (options.view_given) remembered.view = options.view;
  apply_panel_settings(panel, remembered);
  FramePacing pacing;
  while (!window.should_close()) {
    pacing.before_frame(window, panel.idle_wait_s());
    window.begin_frame();
    panel.draw();
    window.end_frame();
  }
  const PanelSettings kept = panel_settings_of(panel);
  try {
    write_panel_settings(file, kept);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "nibrig-panel: the settings were not kept: %s\n", e.what());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  int exit_code = 0;
  const auto options = parse_panel_options(argc, argv, exit_code);
  if (!options) return exit_code;
  try {
    WindowSettings settings;
    settings.width = options->width;
    settings.height = options->height;
    settings.visible = options->screenshot.empty();
    settings.vsync = options->screenshot.empty();
    settings.skip_unchanged = options->screenshot.empty();
    PanelWindow window(settings);
    if (options->screenshot.empty()) return interactive(window, *options);
    Panel panel(options->setup);  // a picture uses nothing remembered: the same every time
    panel.show(options->view);
    return screenshot(window, panel, *options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "nibrig-panel: error: %s\n", e.what());
    return 1;
  }
}
