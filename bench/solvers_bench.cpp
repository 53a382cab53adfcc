// Adapter overhead per model evaluation (docs/performance.md, "Solvers"):
// whole minimize() runs on a trivial model, so nearly all the time is the
// solver's own work plus ours (memo, best-point bookkeeping, FD Jacobian,
// observer record). Counter `per_eval` = run time / model evaluations.
//   ./build/solvers_bench --benchmark_repetitions=5
#include <benchmark/benchmark.h>

#include <span>
#include <string>
#include <vector>

#include "rackopt/solvers/evaluation_tracker.hpp"
#include "rackopt/solvers/solver.hpp"

namespace {

namespace rs = rackopt::solvers;

// Sum of squares around c_i = 0.1 i in n dimensions, one inequality
// (sum x <= n/2, inactive at the optimum for n <= 10) so the constrained
// paths are exercised too. The model itself costs a few ns.
class Trivial : public rs::Problem {
 public:
  explicit Trivial(std::size_t n) : n_(n) {}
  std::size_t dimension() const override { return n_; }
  std::vector<double> lower_bounds() const override { return std::vector<double>(n_, -5.0); }
  std::vector<double> upper_bounds() const override { return std::vector<double>(n_, 5.0); }
  std::size_t num_inequality() const override { return 1; }
  rs::Evaluation evaluate(std::span<const double> x) const override {
    rs::Evaluation e;
    double f = 0, s = 0;
    for (std::size_t i = 0; i < n_; ++i) {
      const double d = x[i] - 0.1 * static_cast<double>(i);
      f += d * d;
      s += x[i];
    }
    e.objectives = {f};
    e.inequality = {s - 0.5 * static_cast<double>(n_)};
    return e;
  }

 private:
  std::size_t n_;
};

// The model alone, called directly: the floor under every per_eval figure.
void BM_ModelOnly(benchmark::State& state) {
  const Trivial p(static_cast<std::size_t>(state.range(0)));
  std::vector<double> x(p.dimension(), 0.3);
  for (auto _ : state) {
    x[0] += 1e-9;
    benchmark::DoNotOptimize(p.evaluate(x));
  }
  state.counters["per_eval"] = benchmark::Counter(static_cast<double>(state.iterations()),
                                                  benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_ModelOnly)->Arg(4)->Arg(16);

// The adapter's own bookkeeping, without a solver: a new point (model call,
// sanitizing, memo insert, best point, history, observer record), a memo
// hit (what a solver revisiting a point costs), and a forward-difference
// Jacobian (n + 1 new points).
rs::SolverSettings unlimited() {
  rs::SolverSettings s;
  s.max_evaluations = std::size_t{1} << 40;
  return s;
}

void BM_TrackerNewPoint(benchmark::State& state) {
  const Trivial p(static_cast<std::size_t>(state.range(0)));
  const rs::SolverSettings s = unlimited();
  std::size_t observed = 0;
  rs::SolverCallbacks cb;
  cb.observer = [&observed](const rs::EvaluationRecord&) { ++observed; };
  rs::detail::EvaluationTracker t(p, s, cb, std::vector<double>(p.dimension(), 0.0));
  std::vector<double> x(p.dimension(), 0.3);
  for (auto _ : state) {
    x[0] += 1e-9;  // always a new point; the memo fills up to its 200000 limit
    benchmark::DoNotOptimize(t.at(x.data()));
  }
  state.counters["per_eval"] = benchmark::Counter(static_cast<double>(state.iterations()),
                                                  benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_TrackerNewPoint)->Arg(4)->Arg(16);

void BM_TrackerMemoHit(benchmark::State& state) {
  const Trivial p(static_cast<std::size_t>(state.range(0)));
  const rs::SolverSettings s = unlimited();
  const rs::SolverCallbacks cb;
  rs::detail::EvaluationTracker t(p, s, cb, std::vector<double>(p.dimension(), 0.0));
  std::vector<double> x(p.dimension(), 0.3);
  for (int k = 0; k < 10000; ++k) {  // a memo of realistic size
    x[0] = 0.3 + 1e-6 * k;
    t.at(x.data());
  }
  x[0] = 0.3 + 1e-6 * 5000;
  for (auto _ : state) benchmark::DoNotOptimize(t.at(x.data()));
}
BENCHMARK(BM_TrackerMemoHit)->Arg(4)->Arg(16);

void BM_TrackerForwardJacobian(benchmark::State& state) {
  const Trivial p(static_cast<std::size_t>(state.range(0)));
  const rs::SolverSettings s = unlimited();
  const rs::SolverCallbacks cb;
  rs::detail::EvaluationTracker t(p, s, cb, std::vector<double>(p.dimension(), 0.0));
  std::vector<double> x(p.dimension(), 0.3);
  double u = 0;
  for (auto _ : state) {
    u += 0.6180339887498949;  // a new center each time, inside the box
    u -= static_cast<double>(static_cast<long>(u));
    x[0] = -4 + 8 * u;
    benchmark::DoNotOptimize(t.jacobian(x.data()).values.data());
  }
  state.counters["per_eval"] = benchmark::Counter(static_cast<double>(state.iterations()) * (state.range(0) + 1),
                                                  benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_TrackerForwardJacobian)->Arg(4)->Arg(16);

// Tolerances off: the budget (or the solver's own end) decides the length.
void run(benchmark::State& state, rs::SolverSettings s, bool with_observer) {
  const Trivial p(static_cast<std::size_t>(state.range(0)));
  const std::vector<double> x0(p.dimension(), 2.0);
  s.xtol_rel = 0;
  s.ftol_rel = 0;
  if (s.library == "ipopt") s.options["ipopt_tol"] = 1e-14;
  rs::SolverCallbacks cb;
  std::size_t observed = 0;
  if (with_observer) cb.observer = [&observed](const rs::EvaluationRecord&) { ++observed; };
  std::size_t evaluations = 0, runs = 0;
  for (auto _ : state) {
    const rs::SolverResult r = rs::minimize(p, x0, s, cb);
    evaluations += r.evaluations;
    ++runs;
    benchmark::DoNotOptimize(r.x.data());
  }
  state.counters["per_eval"] =
      benchmark::Counter(static_cast<double>(evaluations), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["evals_per_run"] = static_cast<double>(evaluations) / static_cast<double>(runs);
}

rs::SolverSettings nlopt(const char* algorithm) {
  rs::SolverSettings s;
  s.algorithm = algorithm;
  s.max_evaluations = 2000;
  return s;
}

void BM_Cobyla(benchmark::State& state) { run(state, nlopt("LN_COBYLA"), true); }
void BM_SlsqpForwardFD(benchmark::State& state) { run(state, nlopt("LD_SLSQP"), true); }
void BM_IpoptCentralFD(benchmark::State& state) {
  rs::SolverSettings s;
  s.library = "ipopt";
  s.max_evaluations = 2000;
  s.central_differences = true;
  run(state, s, true);
}
void BM_IpoptForwardFD(benchmark::State& state) {
  rs::SolverSettings s;
  s.library = "ipopt";
  s.max_evaluations = 2000;
  run(state, s, true);
}
BENCHMARK(BM_Cobyla)->Arg(4)->Arg(16)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SlsqpForwardFD)->Arg(4)->Arg(16)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_IpoptCentralFD)->Arg(4)->Arg(16)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_IpoptForwardFD)->Arg(4)->Arg(16)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
