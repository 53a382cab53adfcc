// Benchmarks of the stiffness core (docs/performance.md records the figures).
//   ./build/stiffness_bench --benchmark_repetitions=5
#include <benchmark/benchmark.h>

#include <string>

#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/stiffness/mesh_ripple.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"
#include "rackopt/stiffness/period_stats.hpp"
#include "rackopt/stiffness/transmission_error.hpp"

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

// The same curve as the stiffness metrics ask for it: each sample's values
// and the exact extremes and mean, no per-pair storage (CurveDetail::kSummary).
void BM_FullSpanCurveSummary(benchmark::State& state) {
  rackopt::Drive d = railway();
  d.numerics.positions_per_period = static_cast<int>(state.range(0));
  for (auto _ : state) {
    rackopt::MeshStiffnessModel model(d);
    benchmark::DoNotOptimize(model.curve(rackopt::CurveDetail::kSummary).k_min);
  }
}
BENCHMARK(BM_FullSpanCurveSummary)->Arg(100)->Arg(25)->Unit(benchmark::kMillisecond);

// What each effect of the FE-grade pair compliance costs on that curve
// (docs/models/fe_calibration.md, "Each effect's share"): 0 the papers'
// tooth model (constant contact term, clamped rack tooth, Sainsot's
// foundation, pairs in parallel), then added in turn 1 the rack foundation,
// 2 the Weber-Banaschek contact, 3 the fillet calibration, 4 the pairs'
// coupling, 5 the supported rack (= the default); 6 the default with the
// constant contact term.
void BM_FullSpanCurveEffects(benchmark::State& state) {
  rackopt::Drive d = railway();
  const int level = static_cast<int>(state.range(0));
  rackopt::Effects& e = d.effects;
  if (level < 6) {
    e.rack_foundation = level >= 1;
    e.hertz = level >= 2 ? rackopt::HertzModel::kWeberBanaschek : rackopt::HertzModel::kLinear;
    e.fillet_calibration = level >= 3;
    e.pair_coupling = level >= 4;
    e.supported_rack = level >= 5;
  } else {
    e.hertz = rackopt::HertzModel::kLinear;
  }
  for (auto _ : state) {
    rackopt::MeshStiffnessModel model(d);
    benchmark::DoNotOptimize(model.curve().k_min);
  }
}
BENCHMARK(BM_FullSpanCurveEffects)->DenseRange(0, 6)->Unit(benchmark::kMillisecond);

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

// The same curve with a long tip and root relief on the pinion (42 um over
// 1.72 modules each): every position with a relieved pair goes through the loaded
// contact solve.
void BM_FullSpanCurveWithRelief(benchmark::State& state) {
  rackopt::Drive d = railway();
  d.pinion.tip_relief = {42e-6, 1.72 * d.pinion.module, rackopt::ProfileRelief::Shape::kLinear};
  d.pinion.root_relief = d.pinion.tip_relief;
  for (auto _ : state) {
    rackopt::MeshStiffnessModel model(d);
    benchmark::DoNotOptimize(model.curve().k_min);
  }
}
BENCHMARK(BM_FullSpanCurveWithRelief)->Unit(benchmark::kMillisecond);

// Per-period statistics on a computed curve: the extra cost of the mesh
// ripple (arg 0) or the transmission error (arg 1) metrics.
void BM_PeriodStats(benchmark::State& state) {
  const rackopt::MeshStiffnessModel model(railway());
  const rackopt::StiffnessCurve curve = model.curve();
  const auto q = state.range(0) == 0 ? rackopt::CurveQuantity::kStiffness : rackopt::CurveQuantity::kApproach;
  for (auto _ : state) benchmark::DoNotOptimize(rackopt::period_stats(model, curve, q).size());
}
BENCHMARK(BM_PeriodStats)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
