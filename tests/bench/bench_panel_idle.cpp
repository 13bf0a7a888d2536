// What the whole panel costs when nothing happens, and what waiting for input costs when something
// does: the real Panel on a space of 62 tools, in a window as nibrig-panel opens it (visible, vsync
// asked for; Xvfb has no vertical blank, so nothing paces the frames but the loop). Each loop runs
// once at full rate (the frame loop unpaced: `/0`) and once paced (FramePacing with
// Panel::idle_wait_s(), and frames whose draw lists did not change not rendered again: `/1`), in
// the same run:
// - PanelIdle: the process's CPU time over 5 s of wall time with nothing moving (`core_percent`,
//   goal < 5) and the frames drawn (`fps`);
// - PanelAnimating: frames per second during a drag on the pad (the picture changes every frame;
//   nothing waits), and how many were rendered;
// - PanelInputLatency: from an event posted to the window's queue (from another thread, every 97
//   ms; it moves the pointer onto a tool or off it) to the end of the first frame begun after it,
//   rendered to the end (`mean_ms`, `max_ms`).
// Run under a display: `xvfb-run -a -s '-screen 0 1280x800x24'` (setup.sh bench does).
#include <benchmark/benchmark.h>

#define GL_GLEXT_PROTOTYPES
#include <GLFW/glfw3.h>

#include <algorithm>
#include <atomic>
#include <functional>
#include <chrono>
#include <cmath>
#include <ctime>
#include <memory>
#include <thread>

#include "imgui.h"
#include "tests/ui/panel/test_space.hpp"
#include "ui/panel/frame_pacing.hpp"
#include "ui/panel/panel.hpp"
#include "ui/panel/panel_window.hpp"

namespace {

namespace panel = nibrig::ui::panel;
using Clock = std::chrono::steady_clock;

double process_cpu_s() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

struct PanelUnderTest {
  std::unique_ptr<panel::PanelWindow> window;
  std::unique_ptr<panel::Panel> ui;
  panel::FramePacing pacing;
  bool paced = false;

  explicit PanelUnderTest(benchmark::State& state) : paced(state.range(0) == 1) {
    try {
      panel::WindowSettings settings;  // as nibrig-panel opens it
      settings.skip_unchanged = paced;
      window = std::make_unique<panel::PanelWindow>(settings);
    } catch (const std::exception& e) {
      state.SkipWithError(e.what());
      return;
    }
    panel::PanelSetup setup;
    setup.space = panel::testing::write_descriptor_space(std::filesystem::path(NIBRIG_TEST_BINARY_DIR) /
                                                         "scratch" / "bench_panel_idle");
    ui = std::make_unique<panel::Panel>(setup);
    const auto deadline = Clock::now() + std::chrono::seconds(60);
    while (!ui->settled() && Clock::now() < deadline) frame();
    for (int i = 0; i < 10; ++i) frame();  // past the settle frames of the last change
  }
  // One pass of nibrig-panel's loop; `input` changes what the back end read (a held button).
  void frame(const std::function<void(ImGuiIO&)>& input = {}) {
    if (paced) pacing.before_frame(*window, ui->idle_wait_s());
    window->begin_frame(input);
    ui->draw();
    window->end_frame();
  }
};

// The process's CPU (% of a core) and the frames per second while the loop runs `seconds` of wall
// time per benchmark iteration, each frame given `input`; reported as counters.
void count_cpu(benchmark::State& state, PanelUnderTest& p, double seconds,
               const std::function<void(ImGuiIO&)>& input = {}) {
  double cpu = 0.0, wall = 0.0;
  std::size_t frames = 0;
  for (auto _ : state) {
    const double cpu0 = process_cpu_s();
    const auto start = Clock::now();
    while (std::chrono::duration<double>(Clock::now() - start).count() < seconds) p.frame(input), ++frames;
    glFinish();
    cpu += process_cpu_s() - cpu0;
    wall += std::chrono::duration<double>(Clock::now() - start).count();
  }
  state.counters["core_percent"] = 100.0 * cpu / wall;
  state.counters["fps"] = static_cast<double>(frames) / wall;
}

void BM_PanelIdle(benchmark::State& state) {
  PanelUnderTest p(state);
  if (!p.ui) return;
  count_cpu(state, p, 5.0);
}
BENCHMARK(BM_PanelIdle)->Arg(0)->Arg(1)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

void BM_PanelAnimating(benchmark::State& state) {
  PanelUnderTest p(state);
  if (!p.ui) return;
  // A drag on the pad: the stroke and the speed trace change every frame, as the rig's waterfall does.
  p.ui->show(panel::View::pad);
  for (int i = 0; i < 5; ++i) p.frame();
  int step = 0;
  const auto drag = [&step](ImGuiIO& io) {
    const double a = 0.05 * step++;
    io.MousePos = {640.0f + 120.0f * static_cast<float>(std::cos(a)), 420.0f + 80.0f * static_cast<float>(std::sin(a))};
    io.MouseDown[0] = true;
  };
  p.frame(drag);  // the press: the drag starts here, before the timing (an idle frame waited for it)
  p.frame(drag);
  const std::size_t rendered = p.window->frames_rendered();
  std::size_t waits = 0;
  for (auto _ : state) {
    p.frame(drag);
    glFinish();
    waits += p.pacing.waited() ? 1 : 0;
  }
  state.counters["rendered"] = static_cast<double>(p.window->frames_rendered() - rendered);
  p.frame();
  state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["waits"] = static_cast<double>(waits);  // frames that waited for input: 0 expected
}
BENCHMARK(BM_PanelAnimating)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);

// A button held still on the space view: nothing waits for input, yet nothing changes. The
// process's CPU over 3 s (`core_percent`) and the frames drawn.
void BM_PanelHeldStill(benchmark::State& state) {
  PanelUnderTest p(state);
  if (!p.ui) return;
  const auto held = [](ImGuiIO& io) {
    io.MousePos = {5.0f, 795.0f};
    io.MouseDown[0] = true;
  };
  p.frame(held);
  count_cpu(state, p, 3.0, held);
  p.frame();
}
BENCHMARK(BM_PanelHeldStill)->Arg(0)->Arg(1)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

void BM_PanelInputLatency(benchmark::State& state) {
  PanelUnderTest p(state);
  if (!p.ui) return;
  // Each event moves the pointer onto a tool or off it again: its tooltip opens or closes, so the
  // frame that answers it is drawn and rendered, whatever skips unchanged frames.
  const ImVec2 tool = p.ui->space_view().screen_position(0).value_or(ImVec2{400.0f, 400.0f});
  const ImVec2 away{5.0f, 795.0f};
  std::atomic<bool> running{true};
  std::atomic<std::int64_t> posted_ns{0};  // when the last event was posted; 0: it was answered
  std::thread poster([&] {
    while (running) {
      std::this_thread::sleep_for(std::chrono::milliseconds(97));
      if (posted_ns.load() != 0) continue;
      posted_ns = Clock::now().time_since_epoch().count();
      glfwPostEmptyEvent();
    }
  });
  double sum_ms = 0.0, max_ms = 0.0;
  std::size_t answered = 0;
  bool on_tool = false;
  for (auto _ : state) {
    const auto start = Clock::now();
    while (Clock::now() - start < std::chrono::seconds(5)) {
      if (p.paced) p.pacing.before_frame(*p.window, p.ui->idle_wait_s());
      const std::int64_t at = posted_ns.load();  // an event before the frame begins: it answers it
      if (at != 0) on_tool = !on_tool;
      p.window->begin_frame([&](ImGuiIO& io) { io.MousePos = on_tool ? tool : away; });
      p.ui->draw();
      p.window->end_frame();
      glFinish();
      if (at == 0) continue;
      const double ms = static_cast<double>(Clock::now().time_since_epoch().count() - at) * 1e-6;
      sum_ms += ms, max_ms = std::max(max_ms, ms), ++answered;
      posted_ns = 0;
    }
  }
  running = false;
  poster.join();
  state.counters["events"] = static_cast<double>(answered);
  state.counters["mean_ms"] = answered ? sum_ms / static_cast<double>(answered) : 0.0;
  state.counters["max_ms"] = max_ms;
}
BENCHMARK(BM_PanelInputLatency)->Arg(0)->Arg(1)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace
