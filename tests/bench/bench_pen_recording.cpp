// Recording a pen stroke: what a row costs the drawing writer (a write each, a flush to disk once a
// second of recording), and what handing a report to the stroke recorder costs the pen reader's
// thread, which also feeds the engine's live contact.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <vector>

#include "model/io/drawing_trajectory_writer.hpp"
#include "rig/pen/stroke_recorder.hpp"

namespace {

using namespace nibrig;

constexpr int kPenBenchReports = 13300;  // 100 s of a tablet at 133 Hz

// Per-call times of one run, as the counters a reader of the benchmark wants: the median, the 99th
// percentile and the longest, in µs.
void set_call_counters(benchmark::State& state, std::vector<double>& us) {
  std::sort(us.begin(), us.end());
  state.counters["median_us"] = us[us.size() / 2];
  state.counters["p99_us"] = us[us.size() * 99 / 100];
  state.counters["max_us"] = us.back();
}

void BM_PenDrawingWriterRows(benchmark::State& state) {
  const auto folder = std::filesystem::path(NIBRIG_TEST_BINARY_DIR) / "bench_pen_writer";
  std::vector<double> us;
  for (auto _ : state) {
    std::filesystem::remove_all(folder);
    us.clear();
    model::io::DrawingTrajectoryWriter writer(folder / "pen_tablet_bench.csv",
                                              {1700000000000LL, 0.0});
    for (int k = 0; k < kPenBenchReports; ++k) {
      model::io::DrawingFrame f;
      f.time_s = k / 133.0;
      f.x_m = 0.1 + 1e-4 * k;
      f.y_m = 0.1;
      f.normal_force_N = 1.0;
      f.touching = true;
      const auto start = std::chrono::steady_clock::now();
      writer.append(f);
      us.push_back(
          std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start)
              .count());
    }
    writer.close();
  }
  set_call_counters(state, us);
  state.SetItemsProcessed(state.iterations() * kPenBenchReports);
}
BENCHMARK(BM_PenDrawingWriterRows)->Unit(benchmark::kMillisecond)->Iterations(3);

// add() as the reader's thread calls it, here back to back (a tablet spaces them 7.5 ms apart).
void BM_PenStrokeRecorderAdd(benchmark::State& state) {
  const auto folder = std::filesystem::path(NIBRIG_TEST_BINARY_DIR) / "bench_pen_recorder";
  std::vector<double> us;
  for (auto _ : state) {
    std::filesystem::remove_all(folder);
    us.clear();
    rig::pen::StrokeRecorder recorder({folder, "pen", "tablet", "bench"});
    recorder.start();
    for (int k = 0; k < kPenBenchReports; ++k) {
      rig::pen::PenSample s;
      s.time_s = 100.0 + k / 133.0;
      s.x_m = 0.1 + 1e-4 * k;
      s.tip_down = true;
      const auto start = std::chrono::steady_clock::now();
      recorder.add(s, 1.0);
      us.push_back(
          std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start)
              .count());
    }
    state.counters["rows"] = static_cast<double>(recorder.stop()->rows);
  }
  set_call_counters(state, us);
}
BENCHMARK(BM_PenStrokeRecorderAdd)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace
