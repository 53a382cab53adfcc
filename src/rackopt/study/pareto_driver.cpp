#include <algorithm>
#include <limits>
#include <stdexcept>

#include "rackopt/solvers/pareto.hpp"
#include "rackopt/study/recorded_problem.hpp"
#include "rackopt/study/study_kind_drivers.hpp"

namespace rackopt::study {

namespace {

// Objective-0 order in the metric's own sense (then the other objectives).
bool front_less(const DesignResult& a, const DesignResult& b) {
  for (std::size_t i = 0; i < a.objectives.size(); ++i) {
    if (a.objectives[i] < b.objectives[i]) return true;
    if (b.objectives[i] < a.objectives[i]) return false;
  }
  return false;
}

}  // namespace

StudyStatus drive_pareto(const KindDriverContext& ctx) {
  const StudySpec& spec = ctx.spec;
  StudyProblem& base = ctx.base;
  EvaluationLedger& ledger = ctx.ledger;
  StudyResult& result = ledger.result();
  const solvers::SolverSettings& solver = ctx.solver;
  const std::size_t combos = base.num_combinations();
  const std::size_t n_obj = spec.objectives.size();
  StudyStatus status = StudyStatus::kOk;
  solvers::ParetoSettings ps = spec.pareto;
  ps.solver = solver;
  std::vector<DesignResult> candidates;
  std::vector<StudyStatus> statuses;
  for (std::size_t c = 0; c < combos; ++c) {
    if (ledger.stop_requested()) break;
    const StudyProblem p = base.for_combination(c);
    const std::string phase = combination_phase(p);
    ledger.set_phase(phase.empty() ? "pareto" : phase);
    RecordedProblem rp(ledger, p);
    rp.set_label(phase);
    if (p.dimension() == 0) {
      const std::vector<double> x = p.to_design({});
      const Obtained o = ledger.obtain(p, x);
      ledger.settle(o, phase, false);
      const DesignResult d = ledger.to_result(o.design, phase);
      if (d.feasible) candidates.push_back(d);
      statuses.push_back(d.feasible ? StudyStatus::kOk : StudyStatus::kNoFeasiblePoint);
      continue;
    }
    solvers::ParetoCallbacks cb;
    cb.observer = [&rp, &ledger, &phase](const std::string& label, const solvers::EvaluationRecord& rec) {
      ledger.set_phase(phase.empty() ? label : phase + ": " + label);
      rp.observed(rec, label);
    };
    cb.stop = [&ledger] { return ledger.stop_requested(); };
    solvers::ParetoResult pr;
    const std::size_t before = result.evaluations;
    try {
      pr = solvers::pareto_front(rp, p.start_unit(), ps, cb);
    } catch (const std::invalid_argument& e) {
      if (result.evaluations != before) throw;
      throw study_error(spec, "solver", e.what());
    }
    rp.settle_pending();
    statuses.push_back(study_status(pr.status));
    for (const solvers::ParetoPoint& fp : pr.front) {
      const std::vector<double> x = p.to_design(fp.x);
      const std::string label = phase.empty() ? fp.label : phase + ": " + fp.label;
      std::optional<DesignEvaluation> o = ledger.recorded(x);
      const DesignEvaluation d = o ? *o : p.evaluate_design(x, ledger.threads());
      DesignResult r = ledger.to_result(d, label);
      if (r.feasible) candidates.push_back(std::move(r));
    }
  }
  // Merge the combinations' fronts: dominance on the minimized (scaled)
  // objectives equals dominance in the metrics' own senses.
  std::vector<std::vector<double>> vectors;
  for (const auto& d : candidates) {
    std::vector<double> v;
    for (std::size_t i = 0; i < n_obj; ++i) {
      const double s = base.objective_scales()[i];
      v.push_back((spec.objectives[i].maximize ? -d.objectives[i] : d.objectives[i]) / s);
    }
    vectors.push_back(std::move(v));
  }
  std::vector<std::vector<double>> kept_vectors;
  for (std::size_t i : solvers::non_dominated(vectors)) {
    result.front.push_back(candidates[i]);
    kept_vectors.push_back(vectors[i]);
  }
  std::vector<std::size_t> order(result.front.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return front_less(result.front[a], result.front[b]); });
  {
    std::vector<DesignResult> f;
    std::vector<std::vector<double>> v;
    for (std::size_t i : order) {
      f.push_back(result.front[i]);
      v.push_back(kept_vectors[i]);
    }
    result.front = std::move(f);
    kept_vectors = std::move(v);
  }
  if (!result.front.empty()) {
    // Chosen: closest to the ideal point (or least weighted sum) with every
    // objective normalized to [0, 1] over the front.
    std::vector<double> ideal(n_obj, std::numeric_limits<double>::infinity()),
        nadir(n_obj, -std::numeric_limits<double>::infinity());
    for (const auto& v : kept_vectors)
      for (std::size_t i = 0; i < n_obj; ++i) {
        ideal[i] = std::min(ideal[i], v[i]);
        nadir[i] = std::max(nadir[i], v[i]);
      }
    const bool weighted = spec.choose_weights.size() == n_obj;
    double best_score = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < kept_vectors.size(); ++k) {
      double score = 0;
      for (std::size_t i = 0; i < n_obj; ++i) {
        const double range = nadir[i] - ideal[i];
        const double t = range > 0 ? (kept_vectors[k][i] - ideal[i]) / range : 0.0;
        score += weighted ? spec.choose_weights[i] * t : t * t;
      }
      if (score < best_score) {
        best_score = score;
        result.chosen = k;
      }
    }
    result.best = result.front[*result.chosen];
  }
  if (ledger.stopped()) {
    status = StudyStatus::kStopped;
  } else if (result.front.empty()) {
    status = ledger.any_ok() ? StudyStatus::kNoFeasiblePoint : StudyStatus::kAllFailed;
  } else {
    status = combos == 1 && !statuses.empty() ? statuses[0] : StudyStatus::kOk;
  }
  return status;
}

}  // namespace rackopt::study
