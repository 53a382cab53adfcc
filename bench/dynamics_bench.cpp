// Benchmarks of the drive dynamics (docs/performance.md, docs/models/dynamics.md):
// one steady response over a support span of 100 mesh periods, its Floquet
// multipliers, and a 50-speed sweep (up and down).
//   ./build/dynamics_bench --benchmark_repetitions=3
//   ./build/dynamics_bench --accuracy      the "Dynamics" tables of docs/accuracy.md
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
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

// Error against a converged reference versus time, for each fidelity knob.
struct Row {
  const char* knob;
  int spm, spn;
  double tol;
};

int accuracy_table() {
  const auto law = representative_law();
  const auto train = representative_train();
  for (double ratio : {0.3, 1.5, 0.5}) {
    const double v = speed_at(ratio);
    rackopt::DynamicsOptions ref;
    ref.steps_per_mesh_period = 1024;
    ref.steps_per_natural_period = 512;
    ref.periodic_tolerance = 1e-9;
    ref.max_periods = 300;
    const auto r0 = rackopt::steady_response(train, law, v, 2e4, ref);
    std::printf("\nmesh frequency %.2f x natural frequency (v = %.3f m/s); reference K_V = %.6f, DTE p-p = %.4f um, %d periods\n",
                ratio, v, r0.dynamic_factor, r0.dte_peak_to_peak * 1e6, r0.periods);
    std::printf("| knob | steps/mesh period | steps/natural period | periodic tolerance | K_V error | DTE p-p error | periods | time [ms] |\n");
    std::printf("|---|---|---|---|---|---|---|---|\n");
    const Row rows[] = {
        {"steps_per_mesh_period", 16, 8, 1e-6},  {"steps_per_mesh_period", 32, 8, 1e-6},
        {"steps_per_mesh_period", 64, 8, 1e-6},  {"steps_per_mesh_period", 128, 8, 1e-6},
        {"steps_per_mesh_period", 256, 8, 1e-6}, {"steps_per_natural_period", 16, 16, 1e-6},
        {"steps_per_natural_period", 16, 32, 1e-6}, {"steps_per_natural_period", 16, 64, 1e-6},
        {"default", 64, 32, 1e-6},
        {"periodic_tolerance", 64, 32, 1e-2}, {"periodic_tolerance", 64, 32, 1e-4},
        {"periodic_tolerance", 64, 32, 1e-8}, {"steps_per_mesh_period", 128, 32, 1e-6},
    };
    for (const Row& row : rows) {
      rackopt::DynamicsOptions o;
      o.steps_per_mesh_period = row.spm;
      o.steps_per_natural_period = row.spn;
      o.periodic_tolerance = row.tol;
      o.max_periods = 300;
      double best = 1e300;
      rackopt::SteadyResponse r;
      for (int rep = 0; rep < 3; ++rep) {
        const auto t0 = std::chrono::steady_clock::now();
        r = rackopt::steady_response(train, law, v, 2e4, o);
        best = std::min(best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
      }
      std::printf("| %s | %d | %d | %.0e | %.1e | %.1e | %d | %.2f |\n", row.knob, row.spm, row.spn, row.tol,
                  std::abs(r.dynamic_factor - r0.dynamic_factor) / r0.dynamic_factor,
                  std::abs(r.dte_peak_to_peak - r0.dte_peak_to_peak) / r0.dte_peak_to_peak, r.periods, best);
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--accuracy") == 0) return accuracy_table();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
