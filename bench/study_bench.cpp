// Study throughput (docs/performance.md, "Studies"):
//  * design evaluations per second of the rack railway sizing problem
//    (StudyProblem::evaluate of studies/rack_railway_sizing.yaml at distinct
//    points), as shipped and stiffness-only, at the file's travel sampling
//    and a coarser one, with the parts of one evaluation timed alone;
//  * the whole rack_railway_sizing study (run_study: evaluations, SQLite
//    record, evaluations.csv; no report);
//  * evaluations per second of the ship lift Pareto problem, with and
//    without its wear metrics;
//  * the 20-point ship lift Pareto front of studies/ship_lift_wear_tradeoff.yaml
//    (one run per repetition: ~10 s each).
//   ./build/study_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
//   ./build/study_bench --benchmark_filter=Evaluate     (the per-design figures only, ~10 s)
#include <unistd.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "rackopt/metrics/evaluate_metrics.hpp"
#include "rackopt/problem/design_point.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"
#include "rackopt/study/study_problem.hpp"
#include "rackopt/study/study_runner.hpp"
#include "rackopt/studyfile/study_loader.hpp"

namespace {

namespace st = rackopt::study;

const std::string kStudies = std::string(RACKOPT_SOURCE_DIR) + "/studies/";

std::filesystem::path bench_root() {
  return std::filesystem::temp_directory_path() / ("rackopt_study_bench_" + std::to_string(::getpid()));
}

// The sizing spec. positions_per_period > 0 sets the metrics' travel
// sampling (metric_options.positions_per_period); 0 keeps the file's.
// stiffness_only drops the stress metrics (contact_safety,
// root_bending_safety, contact_stress): what is left is one stiffness curve
// plus the geometry (contact_ratio) and supports_per_metre.
st::StudySpec sizing_spec(int positions_per_period, bool stiffness_only) {
  st::StudySpec s = rackopt::studyfile::load_study_file(kStudies + "rack_railway_sizing.yaml");
  if (positions_per_period > 0) s.metric_options.positions_per_period = positions_per_period;
  if (stiffness_only) {
    auto stress = [](const std::string& label) { return label.find("safety") != std::string::npos ||
                                                        label.find("stress") != std::string::npos; };
    std::erase_if(s.constraints, [&](const st::ConstraintSpec& c) { return stress(c.label); });
    std::erase_if(s.report_metrics,
                  [&](const rackopt::metrics::MetricRequest& m) { return stress(rackopt::metrics::to_string(m)); });
  }
  return s;
}

// Distinct points of the unit cube, evenly spread (additive recurrence on
// the generalized golden ratio, R_d sequence): every call is a new design, so
// nothing is answered from a cache.
class Points {
 public:
  explicit Points(std::size_t dim) : u_(dim, 0.5), a_(dim) {
    double phi = 2;
    for (int k = 0; k < 50; ++k) phi = std::pow(1 + phi, 1.0 / static_cast<double>(dim + 1));
    for (std::size_t i = 0; i < dim; ++i) a_[i] = std::fmod(std::pow(1 / phi, static_cast<double>(i + 1)), 1.0);
  }
  const std::vector<double>& next() {
    for (std::size_t i = 0; i < u_.size(); ++i) u_[i] = std::fmod(u_[i] + a_[i], 1.0);
    return u_;
  }

 private:
  std::vector<double> u_, a_;
};

void rate_counters(benchmark::State& state, std::size_t failed) {
  state.counters["designs_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["failed"] = static_cast<double>(failed);
}

// StudyProblem::evaluate at distinct designs, the three module values in
// turn: design -> problem tree copy with the values set -> Drive (loader
// checks) -> metrics -> objective/constraint mapping.
// Args: the metrics' positions per period (0 = the file's), stiffness_only (0/1).
void BM_SizingEvaluate(benchmark::State& state) {
  const st::StudyProblem base(sizing_spec(static_cast<int>(state.range(0)), state.range(1) != 0));
  std::vector<st::StudyProblem> views;
  for (std::size_t c = 0; c < base.num_combinations(); ++c) views.push_back(base.for_combination(c));
  Points points(base.dimension());
  std::size_t k = 0, failed = 0;
  for (auto _ : state) {
    const rackopt::solvers::Evaluation e = views[k++ % views.size()].evaluate(points.next());
    failed += e.ok() ? 0 : 1;
    benchmark::DoNotOptimize(e.objectives.data());
  }
  rate_counters(state, failed);
}
BENCHMARK(BM_SizingEvaluate)
    ->ArgNames({"ppp", "stiffness_only"})
    ->Args({0, 0})
    ->Args({0, 1})
    ->Args({24, 0})
    ->Args({24, 1})
    ->Args({100, 0})
    ->Args({100, 1})
    ->Unit(benchmark::kMillisecond);

// The parts of one evaluation, at the same designs (as shipped, file's
// numerics): building the Drive from the problem tree, and each metric
// group alone on a Drive built beforehand.
std::vector<rackopt::Drive> sizing_drives(const st::StudyProblem& base, std::size_t n) {
  std::vector<rackopt::Drive> drives;
  Points points(base.dimension());
  for (std::size_t k = 0; k < n; ++k) {
    const st::StudyProblem view = base.for_combination(k % base.num_combinations());
    drives.push_back(view.drive_at(view.to_design(points.next())));
  }
  return drives;
}

void BM_SizingDriveFromTree(benchmark::State& state) {
  const st::StudyProblem base(sizing_spec(0, false));
  std::vector<st::StudyProblem> views;
  for (std::size_t c = 0; c < base.num_combinations(); ++c) views.push_back(base.for_combination(c));
  Points points(base.dimension());
  std::size_t k = 0;
  for (auto _ : state) {
    const st::StudyProblem& v = views[k++ % views.size()];
    benchmark::DoNotOptimize(v.drive_at(v.to_design(points.next())).rack.span);
  }
  rate_counters(state, 0);
}
BENCHMARK(BM_SizingDriveFromTree)->Unit(benchmark::kMillisecond);

// Metric groups on prepared drives. Arg: 0 = stiffness curve metrics
// (stiffness_fluctuation, min_stiffness_ks, min/mean stiffness), 1 = stress
// metrics (contact_safety, root_bending_safety, contact_stress), 2 =
// contact_ratio, 3 = every metric of the study (what evaluate computes).
void BM_SizingMetricsOnDrive(benchmark::State& state) {
  const st::StudyProblem base(sizing_spec(0, false));
  const std::vector<rackopt::Drive> drives = sizing_drives(base, 64);
  std::vector<rackopt::metrics::MetricRequest> want;
  const auto group = state.range(0);
  for (const auto& m : base.metric_requests()) {
    const std::string l = rackopt::metrics::to_string(m);
    const bool stress = l.find("safety") != std::string::npos || l.find("stress") != std::string::npos;
    const bool stiffness = l.find("stiffness") != std::string::npos;
    if (group == 3 || (group == 0 && stiffness) || (group == 1 && stress) || (group == 2 && l == "contact_ratio"))
      want.push_back(m);
  }
  std::size_t k = 0;
  for (auto _ : state) {
    const auto v = rackopt::metrics::evaluate_metrics(drives[k++ % drives.size()], want, base.spec().metric_options);
    benchmark::DoNotOptimize(v.values.data());
  }
  state.SetLabel(group == 0 ? "stiffness" : group == 1 ? "stress" : group == 2 ? "contact_ratio" : "all");
  rate_counters(state, 0);
}
BENCHMARK(BM_SizingMetricsOnDrive)->Arg(0)->Arg(1)->Arg(2)->Arg(3)->Unit(benchmark::kMillisecond);

// The stiffness curve alone (model + curve + exact extrema) on the same drives.
void BM_SizingStiffnessCurve(benchmark::State& state) {
  const st::StudyProblem base(sizing_spec(0, false));
  const std::vector<rackopt::Drive> drives = sizing_drives(base, 64);
  std::size_t k = 0;
  for (auto _ : state) {
    rackopt::MeshStiffnessModel model(drives[k++ % drives.size()]);
    benchmark::DoNotOptimize(model.curve().k_min);
  }
  rate_counters(state, 0);
}
BENCHMARK(BM_SizingStiffnessCurve)->Unit(benchmark::kMillisecond);

// StudyProblem::evaluate of the ship lift Pareto spec at distinct designs
// (both modules in turn). Arg 0: as shipped (wear_life_at_R(0.9) by the
// exact quantile map, wear_life, stiffness, stresses); 1: the same without
// the two wear metrics, so the difference is the wear model's share.
void BM_ShipLiftEvaluate(benchmark::State& state) {
  st::StudySpec spec = rackopt::studyfile::load_study_file(kStudies + "ship_lift_wear_tradeoff.yaml");
  if (state.range(0) != 0) {
    auto wear = [](const std::string& label) { return label.rfind("wear_life", 0) == 0; };
    std::erase_if(spec.objectives, [&](const st::ObjectiveSpec& o) { return wear(o.label); });
    std::erase_if(spec.report_metrics,
                  [&](const rackopt::metrics::MetricRequest& m) { return wear(rackopt::metrics::to_string(m)); });
  }
  const st::StudyProblem base(spec);
  std::vector<st::StudyProblem> views;
  for (std::size_t c = 0; c < base.num_combinations(); ++c) views.push_back(base.for_combination(c));
  Points points(base.dimension());
  std::size_t k = 0, failed = 0;
  for (auto _ : state) {
    const rackopt::solvers::Evaluation e = views[k++ % views.size()].evaluate(points.next());
    failed += e.ok() ? 0 : 1;
    benchmark::DoNotOptimize(e.objectives.data());
  }
  state.SetLabel(state.range(0) != 0 ? "without wear metrics" : "as shipped");
  rate_counters(state, failed);
}
BENCHMARK(BM_ShipLiftEvaluate)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// A whole study through run_study into a fresh folder (removed between
// iterations, outside the timing). Counters: evaluations of one run and
// time per evaluation.
void run_whole_study(benchmark::State& state, const st::StudySpec& spec, unsigned threads, const std::string& name) {
  std::size_t runs = 0, evaluations = 0;
  for (auto _ : state) {
    state.PauseTiming();
    const auto dir = bench_root() / (name + "_" + std::to_string(runs));
    std::filesystem::remove_all(dir);
    st::RunOptions o;
    o.out_dir = dir.string();
    o.threads = threads;
    state.ResumeTiming();
    const st::StudyResult r = st::run_study(spec, o);
    benchmark::DoNotOptimize(r.evaluations);
    state.PauseTiming();
    evaluations = r.evaluations;
    if (name.find("pareto") != std::string::npos) state.SetLabel(std::to_string(r.front.size()) + " front points");
    std::filesystem::remove_all(dir);
    ++runs;
    state.ResumeTiming();
  }
  state.counters["evaluations"] = static_cast<double>(evaluations);
  state.counters["per_eval"] = benchmark::Counter(static_cast<double>(evaluations * runs),
                                                  benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// studies/rack_railway_sizing.yaml as shipped (3 modules, COBYLA, 300 per
// The gantry sizing problem (studies/gantry_sizing.yaml): the size metrics
// alone on its nominal drive (arg 0: pinion_pitch_diameter, pinion_tip_diameter,
// rack_mass_per_metre, pinion_torque, drive_power: closed forms; arg 1:
// pinion_mass: geometry + outline area; arg 2: cost_per_metre), and (arg 3)
// one whole design evaluation of the study (stresses, contact ratio, wear
// life at R by its exact quantile, the size metrics).
void BM_GantryMetrics(benchmark::State& state) {
  const st::StudySpec spec = rackopt::studyfile::load_study_file(kStudies + "gantry_sizing.yaml");
  const st::StudyProblem base(spec);
  const rackopt::Drive drive = base.drive_at(base.start_design());
  std::vector<rackopt::metrics::MetricRequest> q;
  const int which = static_cast<int>(state.range(0));
  if (which == 0) {
    for (const char* n : {"pinion_pitch_diameter", "pinion_tip_diameter", "rack_mass_per_metre", "pinion_torque",
                          "drive_power"})
      q.push_back(rackopt::metrics::parse_metric_request(n));
  } else if (which == 1) {
    q.push_back(rackopt::metrics::parse_metric_request("pinion_mass"));
  } else if (which == 2) {
    q.push_back(rackopt::metrics::parse_metric_request("cost_per_metre"));
  }
  std::size_t failed = 0;
  for (auto _ : state) {
    if (which == 3) {
      const st::DesignEvaluation d = base.evaluate_design(base.start_design());
      failed += d.evaluation.ok() ? 0 : 1;
      benchmark::DoNotOptimize(d.metric_values.data());
    } else {
      const rackopt::metrics::MetricValues v = rackopt::metrics::evaluate_metrics(drive, q, spec.metric_options);
      failed += v.all_ok() ? 0 : 1;
      benchmark::DoNotOptimize(v.values.data());
    }
  }
  rate_counters(state, failed);
}
BENCHMARK(BM_GantryMetrics)->Arg(0)->Arg(1)->Arg(2)->Arg(3)->Unit(benchmark::kMicrosecond);

// module, xtol_rel 1e-5).
void BM_SizingStudy(benchmark::State& state) {
  run_whole_study(state, sizing_spec(0, false), 1, "sizing");
}
BENCHMARK(BM_SizingStudy)->Unit(benchmark::kMillisecond)->UseRealTime();

// studies/ship_lift_wear_tradeoff.yaml as shipped: 20 points x 2 modules,
// 40 evaluations per sub-problem, exact wear life at R = 0.9 per design.
// Arg: threads given to run_study. About 10 s per run: one iteration per
// repetition.
void BM_ShipLiftPareto(benchmark::State& state) {
  const st::StudySpec spec = rackopt::studyfile::load_study_file(kStudies + "ship_lift_wear_tradeoff.yaml");
  run_whole_study(state, spec, static_cast<unsigned>(state.range(0)), "pareto");
}
BENCHMARK(BM_ShipLiftPareto)
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  std::error_code ec;
  std::filesystem::remove_all(bench_root(), ec);
  return 0;
}
