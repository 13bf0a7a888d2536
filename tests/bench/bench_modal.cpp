// Cost of the mechanics pipeline on a stylus-like body: a Ø10 mm rod, 150 mm long with a
// hemispherical end, meshed by Gmsh with quadratic tetrahedra at 2 mm (what a designer would call
// the default) and 3 mm, then assembly of K and M and the lowest 64 modes. Counters give the size
// of the problem (nodes, free DOFs), the Lanczos work (solves) and f1/f64 so that the accuracy lost
// at the coarser mesh can be read next to the time saved.
#include <benchmark/benchmark.h>

#include <map>
#include <random>

#include "model/mechanics/fem_assembly.hpp"
#include "model/mechanics/modal_analysis.hpp"
#include "model/mechanics/point_probe.hpp"
#include "tests/support/gmsh_tet_mesh.hpp"

namespace {

using namespace nibrig::model::mechanics;

constexpr double kRadius = 5e-3, kLength = 150e-3;
const IsotropicMaterial kVero{"VeroClear", 0.45e9, 0.35, 1180.0};

TetMesh mesh_stylus(double mesh_size) {
  nibrig::test::GmshSession session;
  gmsh::model::add("stylus");
  const int body =
      gmsh::model::occ::addCylinder(0.0, 0.0, 0.0, kLength - kRadius, 0.0, 0.0, kRadius);
  const int ball = gmsh::model::occ::addSphere(kLength - kRadius, 0.0, 0.0, kRadius);
  gmsh::vectorpair fused;
  std::vector<gmsh::vectorpair> map;
  gmsh::model::occ::fuse({{3, body}}, {{3, ball}}, fused, map);
  gmsh::model::occ::synchronize();
  nibrig::test::generate_quadratic_tets(mesh_size);
  return nibrig::test::tet_mesh_from_gmsh();
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
  std::uniform_real_distribution<double> along(0.0, kLength - kRadius), across(-0.6, 0.6);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 1000; ++i)
    points.emplace_back(along(rng), across(rng) * kRadius, across(rng) * kRadius);
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

BENCHMARK(BM_MeshStylus)->Arg(2000)->Arg(3000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Assemble)->Arg(2000)->Arg(3000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Modes64)->Arg(2000)->Arg(3000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LocatePoints)->Arg(2000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MeshAssembleModes64)->Arg(2000)->Arg(3000)->Unit(benchmark::kMillisecond);

}  // namespace
