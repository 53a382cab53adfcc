// Benchmarks of the stiffness core (docs/performance.md records the figures).
//   ./build/stiffness_bench --benchmark_repetitions=5
#include <benchmark/benchmark.h>

#include <string>

#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"

namespace {

rackopt::Drive railway() {
  return rackopt::load_problem(std::string(RACKOPT_SOURCE_DIR) + "/problems/rack_railway.yaml");
}

// One full-span curve of the rack railway (2.4 m, 100 positions per period),
// model construction included: what an optimizer pays per design.
void BM_FullSpanCurveWithModel(benchmark::State& state) {
  rackopt::Drive d = railway();
  d.numerics.positions_per_period = static_cast<int>(state.range(0));
  for (auto _ : state) {
    rackopt::MeshStiffnessModel model(d);
    benchmark::DoNotOptimize(model.curve().k_min);
  }
}
BENCHMARK(BM_FullSpanCurveWithModel)->Arg(100)->Arg(25)->Unit(benchmark::kMillisecond);

void BM_ModelConstruction(benchmark::State& state) {
  const rackopt::Drive d = railway();
  for (auto _ : state) {
    rackopt::MeshStiffnessModel model(d);
    benchmark::DoNotOptimize(&model);
  }
}
BENCHMARK(BM_ModelConstruction)->Unit(benchmark::kMicrosecond);

void BM_SinglePosition(benchmark::State& state) {
  const rackopt::MeshStiffnessModel model(railway());
  double x = 0.1;
  for (auto _ : state) {
    benchmark::DoNotOptimize(model.stiffness(x));
    x = x > 2.3 ? 0.1 : x + 0.0137;
  }
}
BENCHMARK(BM_SinglePosition)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
