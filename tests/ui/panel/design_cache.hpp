// The design tests' shared cache: the demo's forcing model and the coarse design grid
// (panel_test_setup.hpp) are solved once, by DesignCache.SolvesTheCoarseGridOnceForTheDesignTests
// (a CTest fixture, tests/CMakeLists.txt), and the design tests only read them. Solving takes
// three minutes under the sanitizers; done in each test, it also ran beside the JACK session's
// timing check and loaded the machine while the slider's latency was being measured.
#pragma once

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>
#include <thread>

#include "tests/ui/panel/panel_test_setup.hpp"
#include "tests/ui/panel/test_space.hpp"
#include "ui/panel/panel.hpp"

namespace nibrig::ui::panel::testing {

inline std::filesystem::path shared_design_cache() {
  return std::filesystem::path(NIBRIG_TEST_BINARY_DIR) / "scratch" / "panel_design_cache";
}

// Points the user cache at the shared one (a test run alone, outside CTest, fills it itself).
inline void use_shared_design_cache() { ::setenv("NIBRIG_CACHE", shared_design_cache().c_str(), 1); }

// The design tests' panel: the descriptor space written into `dir` (test_space.hpp), the coarse
// grid (panel_test_setup.hpp).
inline PanelSetup design_setup(const std::filesystem::path& dir) {
  PanelSetup setup;
  setup.space = write_descriptor_space(dir);
  setup.design = coarse_design();
  return setup;
}

// The design view on a real JACK server (the actuator at a 64-frame period), in a fresh scratch
// folder `name`, reading the shared cache; one cell centre checked against the FEM.
inline PanelSetup jack_design_setup(const std::string& name) {
  const auto dir = std::filesystem::path(NIBRIG_TEST_BINARY_DIR) / "scratch" / name;
  std::filesystem::remove_all(dir);
  use_shared_design_cache();
  PanelSetup setup = design_setup(dir);
  setup.device = DeviceRequest{"jack", "system", 1, 64};
  setup.design.error_points = 1;
  return setup;
}

// Draws frames until the design view's grid is loaded and its error measured (the panel settled)
// or the deadline passes.
inline void draw_until_design_settled(Panel& panel, const std::function<void()>& frame,
                                      std::chrono::steady_clock::time_point deadline) {
  while (!(panel.settled() && panel.design_view().ready()) && std::chrono::steady_clock::now() < deadline) {
    frame();
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

}  // namespace nibrig::ui::panel::testing
