// Benchmarks of the wear life and of the wear life at reliability R (targets:
// one deterministic life < 1 ms, life at R from 1000
// samples < 100 ms, one core, with one random input and with several). docs/performance.md records the figures.
//   ./build/wear_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
// The 10^4-sample runs without the table take ~10 s per iteration; skip them with
//   --benchmark_filter=-'.*samples:10000.*'
//   ./build/wear_bench --ks_table   (KS critical value vs bootstrap replicates)
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <string>
#include <vector>

#include "rackopt/wear_reliability/wear_reliability.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/statistics/goodness_of_fit.hpp"
#include "rackopt/statistics/reliability.hpp"
#include "rackopt/statistics/sampling.hpp"
#include "rackopt/wear/wear_life.hpp"

namespace {

// The calibrated the wear paper's drive: 240 profile points, update_profile off,
// contact ratio N(1.44, 0.038), R = 0.9 / 0.95 / 0.99, 5 times.
rackopt::Drive ship_lift() {
  return rackopt::load_problem(std::string(RACKOPT_SOURCE_DIR) + "/problems/ship_lift.yaml");
}

// Arguments: profile points (0 = the file's 240), update_profile (0/1, -1 = the file's off).
rackopt::Drive ship_lift_with(long points, long update) {
  rackopt::Drive d = ship_lift();
  if (points > 0) d.wear.profile_points = static_cast<int>(points);
  if (update >= 0) d.wear.update_profile = update != 0;
  return d;
}

// One deterministic life of the nominal drive, model built once. The model
// builds the nominal start (path, unworn load sharing, band weights) on its
// first life only, so this is what a sample that leaves the contact ratio
// and the load alone pays (wear coefficient, hardness); a sample with its
// own contact ratio pays BM_WearLifeSampledContactRatio.
void BM_WearLife(benchmark::State& state) {
  const rackopt::WearModel model(ship_lift_with(state.range(0), state.range(1)));
  rackopt::WearLifeResult r;
  for (auto _ : state) {
    r = model.life();
    benchmark::DoNotOptimize(r.life_cycles);
  }
  state.counters["blocks"] = r.blocks;
  state.counters["life_years"] = r.life_years;
}
BENCHMARK(BM_WearLife)
    ->ArgNames({"points", "update"})
    ->Args({0, -1})   // the file's settings: 240 points, update off
    ->Args({60, 1})   // 60 points, update on, block_fraction 0.02
    ->Args({60, 0})
    ->Args({240, 1})  // the model's defaults: 240 points, update on, block_fraction 0.02
    ->Unit(benchmark::kMillisecond);

// One life of a sampled contact ratio (the path and band weights are rebuilt
// per sample, as in the Monte Carlo loop).
void BM_WearLifeSampledContactRatio(benchmark::State& state) {
  const rackopt::WearModel model(ship_lift_with(state.range(0), state.range(1)));
  double eps = 1.40;
  for (auto _ : state) {
    benchmark::DoNotOptimize(model.life({.contact_ratio = eps}).life_cycles);
    eps = eps > 1.49 ? 1.40 : eps + 0.0037;
  }
}
BENCHMARK(BM_WearLifeSampledContactRatio)
    ->ArgNames({"points", "update"})
    ->Args({0, -1})
    ->Args({60, 1})
    ->Unit(benchmark::kMillisecond);

// Model construction alone (geometry, compliance tables, hardness integrals):
// paid once per design, not per sample.
void BM_WearModelConstruction(benchmark::State& state) {
  const rackopt::Drive d = ship_lift();
  for (auto _ : state) {
    rackopt::WearModel model(d);
    benchmark::DoNotOptimize(&model);
  }
}
BENCHMARK(BM_WearModelConstruction)->Unit(benchmark::kMillisecond);

// The whole life-at-R run on one thread: nominal life, N sampled lives, the
// summary (3 candidate fits, parametric bootstrap for the KS critical values
// and fit intervals) and the exact quantile map. Counters split the wall
// time: samples_ms (the N lives; with the table: building it, ~17 model
// lives, and interpolating), fit_ms (summary + exact map), exact_ms (the
// map: 3 lives at R + 2 polish lives per R(t) time with the table, 305 lives
// by bisection without), nominal_ms, and model lives spent (lives).
// Arguments: samples, profile points (0 = the file's 240), table (1 = the
// one-input life table, 0 = one model life per sample and bisection),
// bootstrap replicates.
void BM_LifeAtR(benchmark::State& state) {
  const rackopt::Drive d = ship_lift_with(state.range(1), -1);
  rackopt::WearReliabilityOptions opt{.samples = state.range(0), .seed = 1, .threads = 1};
  opt.life_table = state.range(2) != 0;
  opt.bootstrap_replicates = static_cast<int>(state.range(3));
  double samples_ms = 0, fit_ms = 0, nominal_ms = 0, exact_ms = 0, lives = 0;
  for (auto _ : state) {
    const rackopt::WearReliabilityResult r = rackopt::run_wear_reliability(d, opt);
    benchmark::DoNotOptimize(r.summary.life.data());
    samples_ms += r.samples_ms;
    fit_ms += r.fit_ms;
    nominal_ms += r.nominal_ms;
    exact_ms += r.exact_ms;
    lives += static_cast<double>(r.table.used ? r.table.evaluations + static_cast<int>(r.table.samples_direct)
                                              : static_cast<int>(r.lives.size())) +
             r.exact.model_evaluations + 1;
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["samples_ms"] = samples_ms / n;
  state.counters["fit_ms"] = fit_ms / n;
  state.counters["exact_ms"] = exact_ms / n;
  state.counters["nominal_ms"] = nominal_ms / n;
  state.counters["lives"] = lives / n;
}
BENCHMARK(BM_LifeAtR)
    ->ArgNames({"samples", "points", "table", "replicates"})
    ->Args({1000, 0, 1, 100})   // the default run (rackopt wear problems/ship_lift.yaml)
    ->Args({1000, 0, 1, 200})
    ->Args({1000, 0, 0, 200})   // before: one life per sample, bisection, 200 replicates
    ->Args({1000, 60, 1, 100})
    ->Args({10000, 0, 1, 100})
    ->Args({10000, 0, 0, 200})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

// The life-at-R run with several random inputs, one thread, 1000 samples,
// 100 bootstrap replicates, the file's 240 points. Arguments: inputs (0 =
// contact ratio + wear coefficient, 1 = contact ratio + wear coefficient +
// surface hardness, 2 = wear coefficient + surface hardness, 3 = contact
// ratio + load), table (1 = the default: the table along the one input that
// shapes the life times each sample's exact factor for the others,
// wear_reliability/life_scaling.hpp; 0 = one model life per sample). With
// inputs 3 both inputs shape the life: the two-input table (table 1) or one
// model life per sample (table 0).
void BM_LifeAtRSeveralInputs(benchmark::State& state) {
  rackopt::Drive d = ship_lift();
  auto relative_normal = [](const char* key, double cv) {
    rackopt::RandomInput in;
    in.key = key;
    in.distribution = rackopt::RandomInput::Distribution::kNormal;
    in.cv = cv;
    return in;
  };
  const rackopt::RandomInput eps = d.reliability.inputs.at(0);  // the file's contact-ratio scatter
  const rackopt::RandomInput k = relative_normal("wear.coefficient", 0.15);
  const rackopt::RandomInput hardness = relative_normal("surface_hardness", 0.05);
  const rackopt::RandomInput load = relative_normal("load", 0.05);
  const long which = state.range(0);
  d.reliability.inputs = which == 0   ? std::vector{eps, k}
                         : which == 1 ? std::vector{eps, k, hardness}
                         : which == 2 ? std::vector{k, hardness}
                                      : std::vector{eps, load};
  rackopt::WearReliabilityOptions opt{.samples = 1000, .seed = 1, .threads = 1};
  opt.life_table = state.range(1) != 0;
  double samples_ms = 0, fit_ms = 0, lives = 0;
  for (auto _ : state) {
    const rackopt::WearReliabilityResult r = rackopt::run_wear_reliability(d, opt);
    benchmark::DoNotOptimize(r.summary.life.data());
    samples_ms += r.samples_ms;
    fit_ms += r.fit_ms;
    lives += static_cast<double>(r.table.evaluations) + static_cast<double>(r.table.samples_direct) + 1;
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["samples_ms"] = samples_ms / n;
  state.counters["fit_ms"] = fit_ms / n;
  state.counters["lives"] = lives / n;
}
BENCHMARK(BM_LifeAtRSeveralInputs)
    ->ArgNames({"inputs", "table"})
    ->Args({0, 1})
    ->Args({0, 0})
    ->Args({1, 1})
    ->Args({2, 1})
    ->Args({3, 1})
    ->Args({3, 0})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

// Lives [s] of an N-sample run of the shipped problem (seed 1), computed once.
const std::vector<double>& lives_seconds(long n) {
  static std::vector<std::vector<double>> cache(2);
  std::vector<double>& v = cache[n > 1000 ? 1 : 0];
  if (v.empty()) {
    const rackopt::WearReliabilityResult r =
        rackopt::run_wear_reliability(ship_lift(), {.samples = n, .seed = 1, .threads = 1, .bootstrap_replicates = 20});
    for (const auto& s : r.lives) v.push_back(s.value);
  }
  return v;
}

// summarize_lives alone (what fit_ms holds besides the exact map), one thread.
// Arguments: samples (1000 or 10000), bootstrap replicates (200 = default, 20 = the minimum).
void BM_SummarizeLives(benchmark::State& state) {
  const std::vector<double>& lives = lives_seconds(state.range(0));
  rackopt::statistics::ReliabilityRequest req;
  req.reliabilities = {0.9, 0.95, 0.99};
  req.bootstrap_replicates = static_cast<int>(state.range(1));
  req.threads = 1;
  for (auto _ : state) {
    const auto s = rackopt::statistics::summarize_lives(lives, req);
    benchmark::DoNotOptimize(s.life.data());
  }
}
BENCHMARK(BM_SummarizeLives)
    ->ArgNames({"samples", "replicates"})
    ->Args({1000, 200})
    ->Args({1000, 100})
    ->Args({1000, 50})
    ->Args({1000, 20})
    ->Args({10000, 200})
    ->Unit(benchmark::kMillisecond);

// The cheap path for an optimizer: the empirical life at R (a copy and a sort)
// and one lognormal MLE fit with its life at R, no bootstrap.
void BM_EmpiricalAndOneFit(benchmark::State& state) {
  const std::vector<double>& lives = lives_seconds(1000);
  std::vector<double> positive;
  std::copy_if(lives.begin(), lives.end(), std::back_inserter(positive), [](double x) { return x > 0; });
  for (auto _ : state) {
    const auto e = rackopt::statistics::empirical_life_at_reliability(lives, 0.9);
    const auto f = rackopt::statistics::fit_life_distribution(rackopt::statistics::Family::kLognormal, positive);
    benchmark::DoNotOptimize(e.estimate + rackopt::statistics::life_at_reliability(f.distribution, 0.9));
  }
}
BENCHMARK(BM_EmpiricalAndOneFit)->Unit(benchmark::kMicrosecond);

// --ks_table: the KS critical value's accuracy against the number of
// bootstrap replicates B, for the fits of the seed-1 lives of the shipped
// problem (docs/models/reliability.md "Bootstrap replicates"): over 100
// bootstrap seeds, the mean, bias and sd of the critical value, how often the
// seed-1 sample is accepted, and the decision with the seed the summary uses.
// Reference: B = 20000. About 3 minutes on 2 threads.
void ks_table() {
  using namespace rackopt::statistics;
  const std::vector<double>& lives = lives_seconds(1000);
  std::vector<double> pos;
  for (double v : lives)
    if (v > 0) pos.push_back(v);
  const Family order[] = {Family::kGamma, Family::kWeibull, Family::kLognormal};  // summary's candidate order
  std::printf("| family | D (seed 1) | B | critical value: mean | bias vs B = 20000 | sd | accepted in (of 100 bootstrap seeds) | shipped bootstrap seed: critical | accepted |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  for (int c = 0; c < 3; ++c) {
    const Family f = order[c];
    const LifeFit fit = fit_life_distribution(f, pos);
    const double D = ks_statistic(fit.distribution, pos);
    const KsTest ref = ks_test_fitted(f, fit.distribution, pos, 0.05, {.replicates = 20000, .seed = 987654321, .threads = 2});
    for (int B : {20, 50, 100, 200, 500, 1000}) {
      std::vector<double> crit;
      int accepted = 0;
      for (int s = 0; s < 100; ++s) {
        const KsTest t = ks_test_fitted(f, fit.distribution, pos, 0.05,
                                        {.replicates = B, .seed = mix64(1000 + static_cast<std::uint64_t>(s)), .threads = 2});
        crit.push_back(t.critical_value);
        accepted += t.accepted ? 1 : 0;
      }
      double m = 0, v = 0;
      for (double x : crit) m += x;
      m /= static_cast<double>(crit.size());
      for (double x : crit) v += (x - m) * (x - m);
      v /= static_cast<double>(crit.size() - 1);
      // The seed summarize_lives uses for candidate c with reliability.seed 1.
      const KsTest shipped = ks_test_fitted(
          f, fit.distribution, pos, 0.05,
          {.replicates = B, .seed = mix64(1 + 0x9E3779B97F4A7C15ULL * static_cast<std::uint64_t>(c + 1)), .threads = 1});
      std::printf("| %s | %.5f | %d | %.5f | %+.5f | %.5f | %d | %.5f | %s |\n", family_name(f), D, B, m,
                  m - ref.critical_value, std::sqrt(v), accepted, shipped.critical_value, shipped.accepted ? "yes" : "no");
    }
    std::printf("| %s | %.5f | 20000 | %.5f (reference; p = %.3f) | | | | | |\n", family_name(f), D, ref.critical_value,
                ref.p_value);
  }
}

}  // namespace

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--ks_table") {
      ks_table();
      return 0;
    }
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
