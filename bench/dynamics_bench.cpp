// Benchmarks of the drive dynamics (docs/performance.md, docs/models/dynamics.md):
// one steady response over a support span of 100 mesh periods, its Floquet
// multipliers, and a 50-speed sweep (up and down).
//   ./build/dynamics_bench --benchmark_repetitions=3
#include <benchmark/benchmark.h>

#include <vector>

#include "dynamics_law.hpp"
#include "rackopt/dynamics/drive_response.hpp"

namespace {

using rackopt::bench::representative_law;
using rackopt::bench::representative_train;

// Speed at which the mesh frequency is `ratio` times the natural frequency.
double speed_at(double ratio) {
  const auto law = representative_law();
  const double fn = rackopt::natural_frequencies_hz(representative_train(), law.mean_stiffness()).front();
  return ratio * fn * law.mesh_pitch;
}

// Arg: mesh frequency / natural frequency in percent.
void BM_SteadyResponse(benchmark::State& state) {
  const auto law = representative_law();
  const auto train = representative_train();
  const double v = speed_at(state.range(0) / 100.0);
  rackopt::DynamicsOptions o;
  for (auto _ : state) benchmark::DoNotOptimize(rackopt::steady_response(train, law, v, 2e4, o).dynamic_factor);
  const auto r = rackopt::steady_response(train, law, v, 2e4, o);
  state.counters["K_V"] = r.dynamic_factor;
  state.counters["periods"] = r.periods;
  state.counters["speed"] = v;
}
BENCHMARK(BM_SteadyResponse)->Arg(50)->Arg(100)->Arg(10)->Unit(benchmark::kMillisecond);

void BM_Floquet(benchmark::State& state) {
  const auto law = representative_law();
  const auto train = representative_train();
  const double v = speed_at(0.5);
  rackopt::DynamicsOptions o;
  for (auto _ : state) benchmark::DoNotOptimize(rackopt::floquet(train, law, v, 2e4, o).spectral_radius);
}
BENCHMARK(BM_Floquet)->Unit(benchmark::kMillisecond);

// 50 speeds from 0.2 to 2 times the resonance speed, both directions.
void BM_Sweep50(benchmark::State& state) {
  const auto law = representative_law();
  const auto train = representative_train();
  std::vector<double> speeds;
  for (int i = 0; i < 50; ++i) speeds.push_back(speed_at(0.2 + 1.8 * i / 49));
  rackopt::DynamicsOptions o;
  for (auto _ : state) benchmark::DoNotOptimize(rackopt::speed_sweep(train, law, speeds, 2e4, o).size());
}
BENCHMARK(BM_Sweep50)->Unit(benchmark::kMillisecond);

}  // namespace
