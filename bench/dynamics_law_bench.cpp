// Benchmarks of building the dynamic model's inputs from the static model
// (docs/models/dynamics.md, "Mesh force law"; docs/performance.md).
//   ./build/dynamics_law_bench --benchmark_repetitions=5
#include <benchmark/benchmark.h>

#include <string>

#include "rackopt/dynamics/mesh_force_law_builder.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"

namespace {

rackopt::Drive gantry() {
  return rackopt::load_problem(std::string(RACKOPT_SOURCE_DIR) + "/problems/gantry_axis.yaml");
}

// The gantry axis's law over one span (0.5 m, 40 mesh periods) from a built
// model, at range(0) positions per period: the curve (its full per-pair
// detail), the corner slots and the path-end states.
void BM_GantryMeshForceLaw(benchmark::State& state) {
  const rackopt::Drive d = gantry();
  const rackopt::MeshStiffnessModel model(d);
  for (auto _ : state) {
    benchmark::DoNotOptimize(rackopt::build_mesh_force_law(d, model, static_cast<int>(state.range(0))).travel.size());
  }
}
BENCHMARK(BM_GantryMeshForceLaw)->Arg(100)->Arg(25)->Unit(benchmark::kMillisecond);

// The same without corner contact: what the corner slots cost.
void BM_GantryMeshForceLawNoCorners(benchmark::State& state) {
  const rackopt::Drive d = gantry();
  const rackopt::MeshStiffnessModel model(d);
  rackopt::MeshForceLawOptions off;
  off.corner_contact = false;
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        rackopt::build_mesh_force_law(d, model, static_cast<int>(state.range(0)), off).travel.size());
  }
}
BENCHMARK(BM_GantryMeshForceLawNoCorners)->Arg(100)->Unit(benchmark::kMillisecond);

// The stiffness curve alone at the same detail, for comparison.
void BM_GantryCurve(benchmark::State& state) {
  const rackopt::Drive d = gantry();
  const rackopt::MeshStiffnessModel model(d);
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        model.curve(rackopt::CurveDetail::kFull, static_cast<int>(state.range(0))).samples.size());
  }
}
BENCHMARK(BM_GantryCurve)->Arg(100)->Unit(benchmark::kMillisecond);

// Model construction plus the law: what a design pays.
void BM_GantryModelAndLaw(benchmark::State& state) {
  const rackopt::Drive d = gantry();
  for (auto _ : state) {
    const rackopt::MeshStiffnessModel model(d);
    benchmark::DoNotOptimize(rackopt::build_mesh_force_law(d, model).travel.size());
  }
}
BENCHMARK(BM_GantryModelAndLaw)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
