// nibrig-panel: the window. Everything it shows is in the nibrig_panel library (ui/panel/panel.hpp);
// this file opens the window and runs the frame loop, or renders one view into a PNG.
#include <chrono>
#include <cstdio>
#include <exception>
#include <thread>

#include "ui/panel/panel.hpp"
#include "ui/panel/panel_options.hpp"
#include "ui/panel/panel_window.hpp"

int main(int argc, char** argv) {
  using namespace nibrig::ui::panel;
  int exit_code = 0;
  const auto options = parse_panel_options(argc, argv, exit_code);
  if (!options) return exit_code;
  try {
    WindowSettings settings;
    settings.width = options->width;
    settings.height = options->height;
    settings.visible = options->screenshot.empty();
    settings.vsync = options->screenshot.empty();
    PanelWindow window(settings);
    Panel panel(options->setup);
    panel.show(options->view);
    if (!options->screenshot.empty()) {
      // Draw until the view has loaded what it shows (or the timeout), then the frames asked for.
      const auto deadline = std::chrono::steady_clock::now() +
                            std::chrono::duration<double>(options->settle_timeout_s);
      int settled_frames = 0;
      while (settled_frames < options->frames) {
        window.begin_frame();
        panel.draw();
        const bool last = settled_frames + 1 == options->frames &&
                          (panel.settled() || std::chrono::steady_clock::now() > deadline);
        window.end_frame(last ? options->screenshot : std::filesystem::path());
        if (panel.settled() || std::chrono::steady_clock::now() > deadline) ++settled_frames;
        else std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
      std::printf("wrote %s\n", options->screenshot.c_str());
      return 0;
    }
    while (!window.should_close()) {
      window.begin_frame();
      panel.draw();
      window.end_frame();
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "nibrig-panel: error: %s\n", e.what());
    return 1;
  }
}
