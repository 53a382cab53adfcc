#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

#include "rackopt/core/interrupt.hpp"
#include "rackopt/doe/samplers.hpp"
#include "rackopt/study/study_kind_drivers.hpp"
#include "rackopt/study/sweep_sensitivity.hpp"

namespace rackopt::study {

std::vector<std::vector<double>> sweep_points(const StudySpec& spec) {
  const auto& vars = spec.variables;
  try {
    if (spec.sweep.method == SweepSpec::Method::kGrid) {
      std::vector<std::vector<double>> levels;
      for (const auto& v : vars) {
        if (v.discrete()) {
          levels.push_back(v.values);
        } else {
          levels.push_back(doe::linspace_levels(v.lower, v.upper, v.levels.value_or(spec.sweep.levels)));
        }
      }
      return doe::full_grid(levels, spec.sweep.max_points);
    }
    std::vector<double> lo, hi;
    for (const auto& v : vars) {
      lo.push_back(v.lower);
      hi.push_back(v.upper);
    }
    std::vector<std::vector<double>> pts =
        spec.sweep.method == SweepSpec::Method::kSobol ? doe::sobol_points(lo, hi, spec.sweep.points, spec.seed)
                                                       : doe::latin_hypercube(lo, hi, spec.sweep.points, spec.seed);
    // Discrete variables: the nearest allowed value (the lower one on a tie).
    for (auto& p : pts) {
      for (std::size_t i = 0; i < vars.size(); ++i) {
        if (!vars[i].discrete()) continue;
        const auto& vals = vars[i].values;
        double best = vals.front();
        for (double v : vals)
          if (std::abs(v - p[i]) < std::abs(best - p[i])) best = v;
        p[i] = best;
      }
    }
    return pts;
  } catch (const std::invalid_argument& e) {
    throw study_error(spec, "sweep", std::string("cannot build the sweep: ") + e.what());
  }
}

StudyStatus drive_sweep(const KindDriverContext& ctx, const std::vector<std::vector<double>>& points) {
  const StudySpec& spec = ctx.spec;
  StudyProblem& base = ctx.base;
  EvaluationLedger& ledger = ctx.ledger;
  StudyResult& result = ledger.result();
  const std::size_t n_obj = spec.objectives.size();
  StudyStatus status = StudyStatus::kOk;
  ledger.set_phase("sweep");
  const std::size_t chunk = std::max<std::size_t>(8, 8 * static_cast<std::size_t>(ledger.executor().workers()));
  for (std::size_t begin = 0; begin < points.size(); begin += chunk) {
    if (ledger.stop_requested()) break;
    const std::size_t end = std::min(points.size(), begin + chunk);
    const std::size_t n = end - begin;
    // Per chunk: store hits and in-chunk duplicates on this thread, the
    // rest in parallel, then everything recorded in sampler order (so the
    // store and the result do not depend on the thread count).
    std::vector<std::vector<double>> xs(points.begin() + static_cast<std::ptrdiff_t>(begin),
                                        points.begin() + static_cast<std::ptrdiff_t>(end));
    std::vector<std::optional<Obtained>> got(n);
    std::vector<std::optional<DesignEvaluation>> fresh(n);
    std::vector<std::size_t> misses;
    std::unordered_map<std::string, std::size_t> first_in_chunk;
    std::vector<std::size_t> duplicate_of(n, SIZE_MAX);
    for (std::size_t k = 0; k < n; ++k) {
      const std::string key = bits_key(xs[k]);
      if (auto it = first_in_chunk.find(key); it != first_in_chunk.end()) {
        duplicate_of[k] = it->second;
        continue;
      }
      first_in_chunk.emplace(key, k);
      got[k] = ledger.lookup(xs[k]);
      if (!got[k]) misses.push_back(k);
    }
    // The misses on the ledger's executor (threads or MPI ranks).
    std::vector<std::vector<double>> miss_xs;
    for (std::size_t k : misses) miss_xs.push_back(xs[k]);
    if (!miss_xs.empty()) {
      std::vector<DesignEvaluation> computed;
      try {
        computed = ledger.executor().evaluate(base, miss_xs, ledger.threads());
      } catch (const Interrupted&) {
        // Ctrl-C inside an evaluation (a Monte Carlo life at R): the chunk
        // is abandoned, --resume evaluates it again; the report is written.
        ledger.mark_stopped();
        break;
      }
      for (std::size_t j = 0; j < misses.size(); ++j) fresh[misses[j]] = std::move(computed[j]);
    }
    for (std::size_t k = 0; k < n; ++k) {
      const std::string label = "sweep " + std::to_string(begin + k);
      const std::size_t j = duplicate_of[k] != SIZE_MAX ? duplicate_of[k] : k;
      Obtained o = got[j] ? *got[j] : Obtained{*fresh[j], Origin::kNew, 0};
      if (j != k) o.origin = Origin::kRepeat;
      ledger.settle(o, label, false);  // ranks: progress and history show the best so far
      result.sweep_points.push_back(ledger.to_result(o.design, label));
    }
  }
  status = ledger.stopped() ? StudyStatus::kStopped : StudyStatus::kOk;
  if (n_obj > 0) {
    const bool maximize = spec.objectives[0].maximize;
    for (const DesignResult& p : result.sweep_points) {
      if (!p.feasible) continue;
      if (!result.best || (maximize ? p.objectives[0] > result.best->objectives[0]
                                    : p.objectives[0] < result.best->objectives[0]))
        result.best = p;
    }
  }
  // A sweep without objectives has no best; the least infeasible point
  // only means something when no point is feasible.
  const bool any_feasible = std::any_of(result.sweep_points.begin(), result.sweep_points.end(),
                                        [](const DesignResult& p) { return p.feasible; });
  if (!result.best && !any_feasible) {
    for (const DesignResult& p : result.sweep_points)
      if (p.ok && (!result.least_infeasible || p.max_violation < result.least_infeasible->max_violation))
        result.least_infeasible = p;
  }
  if (!result.sweep_points.empty()) result.sensitivity = sweep_sensitivity(spec, result.sweep_points);
  if (!result.sweep_points.empty() && !ledger.stopped()) {
    bool any_ok = false;
    for (const auto& p : result.sweep_points) any_ok = any_ok || p.ok;
    if (!any_ok) status = StudyStatus::kAllFailed;
  }
  return status;
}

}  // namespace rackopt::study
