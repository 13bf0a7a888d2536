// Cost of the mechanics pipeline on the bundled stylus design
// (assets/designs/stylus_vero_tip1mm.json: Ø10 × 120 mm body, 15 mm taper, 1 mm hemispherical tip),
// meshed by Gmsh with quadratic tetrahedra at its default 3 mm and at 2 mm, then assembly of K and
// M and the lowest 64 modes. Counters give the size of the problem (nodes, free DOFs), the Lanczos
// work (solves) and f1/f64 so that the accuracy lost at the coarser mesh can be read next to the
// time saved.
#include <benchmark/benchmark.h>

#include <map>
#include <random>

#include "model/mechanics/design_model.hpp"
#include "model/mechanics/fem_assembly.hpp"
#include "model/mechanics/modal_analysis.hpp"
#include "model/mechanics/point_probe.hpp"
#include "model/mechanics/stylus_description.hpp"
#include "tests/support/test_paths.hpp"

namespace {

using namespace nibrig::model::mechanics;

const IsotropicMaterial kVero{"VeroClear", 0.45e9, 0.35, 1185.0};

const Design& bundled_stylus() {
  static const Design design =
      read_design(nibrig::test::assets_dir() / "designs" / "stylus_vero_tip1mm.json",
                  read_material_table(nibrig::test::assets_dir() / "materials.json"));
  return design;
}

TetMesh mesh_stylus(double mesh_size) {
  return nibrig::model::mechanics::mesh_stylus(std::get<StylusGeometry>(bundled_stylus().shape),
                                               mesh_size);
}

// Meshes are made once per size and shared by the assembly and modal benchmarks.
const TetMesh& stylus(double mesh_size) {
  static std::map<double, TetMesh> cache;
  auto it = cache.find(mesh_size);
  if (it == cache.end()) it = cache.emplace(mesh_size, mesh_stylus(mesh_size)).first;
  return it->second;
}

double mesh_size_of(const benchmark::State& state) {
  return static_cast<double>(state.range(0)) * 1e-6;  // argument in µm
}

void size_counters(benchmark::State& state, const TetMesh& mesh, const FemSystem& sys) {
  state.counters["nodes"] = static_cast<double>(mesh.nodes.cols());
  state.counters["tets"] = static_cast<double>(mesh.tets.size());
  state.counters["free_dofs"] = static_cast<double>(sys.free_dofs());
}

void BM_MeshStylus(benchmark::State& state) {
  for (auto _ : state) {
    const TetMesh mesh = mesh_stylus(mesh_size_of(state));
    benchmark::DoNotOptimize(mesh.nodes.data());
    state.counters["nodes"] = static_cast<double>(mesh.nodes.cols());
  }
}

void BM_Assemble(benchmark::State& state) {
  const TetMesh& mesh = stylus(mesh_size_of(state));
  FemSystem sys;
  for (auto _ : state) {
    sys = assemble(mesh, {kVero}, {"clamp"});
    benchmark::DoNotOptimize(sys.stiffness.valuePtr());
  }
  size_counters(state, mesh, sys);
  state.counters["nonzeros_K"] = static_cast<double>(sys.stiffness.nonZeros());
}

void BM_Modes64(benchmark::State& state) {
  const TetMesh& mesh = stylus(mesh_size_of(state));
  const FemSystem sys = assemble(mesh, {kVero}, {"clamp"});
  ModalResult r;
  for (auto _ : state) {
    r = compute_modes(sys, {});
    benchmark::DoNotOptimize(r.shapes.data());
  }
  size_counters(state, mesh, sys);
  state.counters["solves"] = r.solves;
  state.counters["f1_hz"] = r.frequency_hz(0);
  state.counters["f64_hz"] = r.frequency_hz(r.frequency_hz.size() - 1);
}

// Building the search grid, then finding 1000 random points of the rod (per iteration).
void BM_LocatePoints(benchmark::State& state) {
  const TetMesh& mesh = stylus(mesh_size_of(state));
  std::mt19937 rng(1);
  const auto& geometry = std::get<StylusGeometry>(bundled_stylus().shape);
  const double radius = geometry.body_diameter / 2;
  std::uniform_real_distribution<double> along(0.0, geometry.body_length), across(-0.6, 0.6);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 1000; ++i)
    points.emplace_back(along(rng), across(rng) * radius, across(rng) * radius);
  double weight_sum = 0.0;
  for (auto _ : state) {
    const PointLocator locator(mesh);
    for (const auto& p : points) weight_sum += locator.locate(p).weights.sum();
  }
  benchmark::DoNotOptimize(weight_sum);
  state.counters["tets"] = static_cast<double>(mesh.tets.size());
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(points.size()));
}

// What a design iteration costs end to end: mesh, assemble, 64 modes.
void BM_MeshAssembleModes64(benchmark::State& state) {
  for (auto _ : state) {
    const TetMesh mesh = mesh_stylus(mesh_size_of(state));
    const FemSystem sys = assemble(mesh, {kVero}, {"clamp"});
    const ModalResult r = compute_modes(sys, {});
    benchmark::DoNotOptimize(r.shapes.data());
    state.counters["nodes"] = static_cast<double>(mesh.nodes.cols());
  }
}

// The whole pipeline as `nibrig mechanics modes` runs it on the bundled design (its 64 modes at
// 3 mm), including locating tip and sensor and damping: the figure the 2 s target is about.
void BM_DesignToModalModel(benchmark::State& state) {
  const auto materials = read_material_table(nibrig::test::assets_dir() / "materials.json");
  for (auto _ : state) {
    const DesignModel model = build_design_model(bundled_stylus(), materials);
    benchmark::DoNotOptimize(model.modal.omega.data());
    state.counters["free_dofs"] = static_cast<double>(model.free_dofs);
    state.counters["modes"] = static_cast<double>(model.modal.size());
  }
}

BENCHMARK(BM_DesignToModalModel)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MeshStylus)->Arg(2000)->Arg(3000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Assemble)->Arg(2000)->Arg(3000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Modes64)->Arg(2000)->Arg(3000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LocatePoints)->Arg(2000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MeshAssembleModes64)->Arg(2000)->Arg(3000)->Unit(benchmark::kMillisecond);

}  // namespace
