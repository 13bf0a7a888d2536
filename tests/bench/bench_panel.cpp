// What a frame of the panel costs on this machine's OpenGL (Mesa llvmpipe under Xvfb: no GPU): the
// space with 200 tools and their 68/95 % regions beside two live spectrograms, each taking a new row
// per frame (the analysis makes one every 21 ms), drawn and rendered to the end (glFinish). Beside
// it, in the same run, an empty frame: the window, ImGui and the swap alone. The goal is >= 60
// frames per second (`fps`). Run under a display: `xvfb-run -a -s '-screen 0 1280x800x24'` (setup.sh
// bench does).
#include <benchmark/benchmark.h>

#define GL_GLEXT_PROTOTYPES
#include <GLFW/glfw3.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "imgui.h"
#include "ui/panel/panel_window.hpp"
#include "ui/panel/space_view.hpp"
#include "ui/panel/waterfall.hpp"

namespace {

namespace panel = nibrig::ui::panel;

panel::SpaceScene two_hundred_tools() {
  panel::SpaceScene scene;
  scene.axis_names = {"axis 1", "axis 2"};
  scene.surfaces = {"office", "note", "stone", "glass", "protector"};
  std::mt19937 rng(3);
  std::normal_distribution<double> place(0.0, 2.0), spread(0.3, 0.05);
  const char* kinds[] = {"real", "printed", "commercial", "predicted"};
  for (int i = 0; i < 200; ++i) {
    panel::SceneTool t;
    t.choice = {"tool" + std::to_string(i), scene.surfaces[static_cast<std::size_t>(i) % 5]};
    t.label = t.choice.tool;
    t.kind = kinds[i % 4];
    t.judged = i % 3 == 0;
    t.region.mean = Eigen::Vector2d(place(rng), place(rng));
    const double a = spread(rng), b = spread(rng);
    t.region.covariance = Eigen::Matrix2d{{a * a, 0.3 * a * b}, {0.3 * a * b, b * b}};
    t.region.radius = {1.51, 2.45};  // χ²(2) at 68 % and 95 %
    scene.tools.push_back(std::move(t));
  }
  return scene;
}

std::unique_ptr<panel::PanelWindow> open_window(benchmark::State& state) {
  panel::WindowSettings w;
  w.visible = false;
  w.vsync = false;  // measure the frame, not the display's refresh
  try {
    return std::make_unique<panel::PanelWindow>(w);
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return nullptr;
  }
}

void BM_PanelFrameSpace200AndTwoSpectrograms(benchmark::State& state) {
  auto window = open_window(state);
  if (!window) return;
  panel::SpaceView view(two_hundred_tools(), {});
  // The rig's waterfalls: 43 bins (0-500 Hz at 11.7 Hz) × 480 rows (10 s); here 350 bins (0-4 kHz),
  // more than the panel shows, so that the upload is not understated.
  const std::size_t bins = 350;
  panel::Waterfall measured(bins, 480, panel::Waterfall::Scale::sequential, -60, 20);
  panel::Waterfall simulated(bins, 480, panel::Waterfall::Scale::sequential, -60, 20);
  std::vector<float> row(bins);
  std::mt19937 rng(5);
  std::normal_distribution<float> level(-30.0f, 10.0f);
  for (auto _ : state) {
    for (float& v : row) v = level(rng);
    measured.push_row(row.data());
    simulated.push_row(row.data());
    window->begin_frame();
    const ImGuiViewport* vp = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(vp->WorkPos);
    ImGui::SetNextWindowSize(vp->WorkSize);
    ImGui::Begin("bench", nullptr, ImGuiWindowFlags_NoDecoration);
    ImGui::BeginChild("space", {vp->WorkSize.x * 0.55f, 0});
    view.draw();
    ImGui::EndChild();
    ImGui::SameLine();
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 at = ImGui::GetCursorScreenPos();
    measured.draw(draw, at, {at.x + 250, at.y + 330});
    simulated.draw(draw, {at.x + 270, at.y}, {at.x + 520, at.y + 330});
    ImGui::End();
    window->end_frame();
    glFinish();
  }
  state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_PanelFrameSpace200AndTwoSpectrograms)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);

void BM_PanelFrameEmpty(benchmark::State& state) {
  auto window = open_window(state);
  if (!window) return;
  for (auto _ : state) {
    window->begin_frame();
    ImGui::Begin("bench", nullptr, ImGuiWindowFlags_NoDecoration);
    ImGui::TextUnformatted("an empty frame");
    ImGui::End();
    window->end_frame();
    glFinish();
  }
  state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_PanelFrameEmpty)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);

}  // namespace
