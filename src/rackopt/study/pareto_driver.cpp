#include <algorithm>
#include <limits>
#include <stdexcept>

#include "rackopt/core/interrupt.hpp"
#include "rackopt/core/text.hpp"
#include "rackopt/solvers/front_selection.hpp"
#include "rackopt/solvers/pareto.hpp"
#include "rackopt/study/combination_runs.hpp"
#include "rackopt/study/front_summary.hpp"
#include "rackopt/study/recorded_problem.hpp"
#include "rackopt/study/study_kind_drivers.hpp"
#include "rackopt/study/study_kind_rules.hpp"

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
  const std::size_t n_obj = spec.objectives.size();
  StudyStatus status = StudyStatus::kOk;
  solvers::ParetoSettings ps = spec.pareto;
  ps.solver = solver;
  std::vector<DesignResult> candidates;
  std::vector<std::size_t> candidate_run;  // the run (combination) that gave each candidate
  // Each run's phase text and how many front points it gave.
  std::vector<std::pair<std::string, std::size_t>> combination_of_front;
  std::vector<std::string> shortfall;
  std::vector<StudyStatus> statuses;
  // One run per combination (the runs in lockstep: each round's designs of
  // every combination go to the executor as one batch), or one run over
  // them all when the algorithm searches the discrete variables as integers.
  CombinationRuns runs(ledger, base, solver_views(base), combination_phase);
  std::vector<std::optional<solvers::ParetoResult>> run_results(runs.size());
  std::vector<char> ran(runs.size(), 0);
  const std::size_t before = result.evaluations;
  try {
    runs.run([&](std::size_t c, const solvers::Problem& problem) {
      if (ledger.stop_requested()) return;
      ran[c] = 1;
      const StudyProblem& p = runs.view(c);
      const RecordedProblem& rp = runs.recorded(c);
      const std::string phase = combination_phase(p);
      ledger.set_phase(phase.empty() ? "pareto" : phase);
      if (p.dimension() == 0) {
        problem.evaluate_batch({std::vector<double>{}});
        rp.settle_pending();
        return;
      }
      solvers::ParetoCallbacks cb;
      cb.observer = [&](const std::string& label, const solvers::EvaluationRecord& rec) {
        ledger.set_phase(phase.empty() ? label : phase + ": " + label);
        rp.observed(rec, label);
      };
      cb.stop = [&ledger] { return ledger.stop_requested(); };
      run_results[c] = solvers::pareto_front(problem, p.start_unit(), ps, cb);
      rp.settle_pending();
    });
  } catch (const std::invalid_argument& e) {
    if (result.evaluations != before) throw;
    throw study_error(spec, "solver", e.what());
  }
  for (std::size_t c = 0; c < runs.size(); ++c) {
    if (!ran[c]) break;  // stopped before it
    const StudyProblem& p = runs.view(c);
    const std::string phase = combination_phase(p);
    if (p.dimension() == 0) {
      const std::vector<double> x = p.to_design({});
      const std::optional<DesignEvaluation> o = ledger.recorded(x);
      if (!o) break;  // stopped inside its round
      const DesignResult d = ledger.to_result(*o, phase);
      if (d.feasible) {
        candidates.push_back(d);
        candidate_run.push_back(c);
      }
      combination_of_front.push_back({phase, d.feasible ? 1u : 0u});
      statuses.push_back(d.feasible ? StudyStatus::kOk : StudyStatus::kNoFeasiblePoint);
      continue;
    }
    if (!run_results[c]) break;
    const solvers::ParetoResult& pr = *run_results[c];
    statuses.push_back(study_status(pr.status));
    const std::string where = phase.empty() ? "" : phase + ": ";
    for (const solvers::ParetoPoint& ip : pr.infeasible)
      shortfall.push_back(where + ip.label + " found no feasible design" +
                          (ip.evaluation.ok() ? "" : " (" + ip.evaluation.message + ")"));
    if (!pr.dominated.empty()) {
      std::vector<std::string> labels;
      for (const solvers::ParetoPoint& dp : pr.dominated) labels.push_back(dp.label);
      shortfall.push_back(where + join(labels) + (labels.size() == 1 ? " gave a design" : " gave designs") +
                          " dominated by, or within pareto.duplicate_tolerance of, another front point");
    }
    if (spec.pareto.method == solvers::Scalarization::kPopulation && pr.front.size() < spec.pareto.points)
      shortfall.push_back(where + spec.solver.algorithm + " found " + std::to_string(pr.front.size()) +
                          " distinct non-dominated feasible designs in " + std::to_string(pr.evaluations) +
                          " evaluations (" + std::to_string(pr.generations) + " generations of " +
                          std::to_string(pr.population) + "); raise max_evaluations or population");
    const std::size_t first_candidate = candidates.size();
    for (const solvers::ParetoPoint& fp : pr.front) {
      const std::vector<double> x = p.to_design(fp.x);
      const std::string label = phase.empty() ? fp.label : phase + ": " + fp.label;
      std::optional<DesignEvaluation> o = ledger.recorded(x);
      if (!o) {
        try {
          o = p.evaluate_design(x, ledger.threads());
        } catch (const Interrupted&) {
          // Ctrl-C inside its Monte Carlo: the point is left out of the
          // stopped study's front (--resume finds it again).
          ledger.mark_stopped();
          continue;
        }
      }
      DesignResult r = ledger.to_result(*o, label);
      if (r.feasible) {
        candidates.push_back(std::move(r));
        candidate_run.push_back(c);
      }
    }
    combination_of_front.push_back({phase, candidates.size() - first_candidate});
  }
  // Merge the combinations' fronts: dominance on the minimized (scaled)
  // objectives equals dominance in the metrics' own senses. The merged
  // front follows the rule of one front (non-dominated, no near-duplicates,
  // at most pareto.points, thinned by crowding).
  auto minimized_scaled = [&](const DesignResult& d) {
    std::vector<double> v;
    for (std::size_t i = 0; i < n_obj; ++i) {
      const double s = base.objective_scales()[i];
      v.push_back((spec.objectives[i].maximize ? -d.objectives[i] : d.objectives[i]) / s);
    }
    return v;
  };
  std::vector<std::vector<double>> vectors;
  for (const auto& d : candidates) vectors.push_back(minimized_scaled(d));
  std::vector<std::vector<double>> kept_vectors;
  std::vector<std::size_t> kept_per_run(runs.size(), 0);
  std::vector<std::size_t> kept =
      solvers::select_front_indices(vectors, spec.pareto.points, spec.pareto.duplicate_tolerance);
  // Reported in objective 0's own sense, ascending (then the others).
  std::stable_sort(kept.begin(), kept.end(),
                   [&](std::size_t a, std::size_t b) { return front_less(candidates[a], candidates[b]); });
  for (std::size_t i : kept) {
    result.front.push_back(candidates[i]);
    kept_vectors.push_back(vectors[i]);
    ++kept_per_run[candidate_run[i]];
  }
  if (runs.size() > 1 && result.front.size() < spec.pareto.points) {
    for (std::size_t c = 0; c < combination_of_front.size(); ++c) {
      const auto& [phase, given] = combination_of_front[c];
      if (given > kept_per_run[c])
        shortfall.push_back(phase + ": " + std::to_string(given - kept_per_run[c]) + " of its " +
                            std::to_string(given) + " front points are dominated by other combinations' points");
    }
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
  {
    FrontSummary summary;
    if (!kept_vectors.empty()) {
      // Minimized own units: the scaled vectors times their scales.
      std::vector<std::vector<double>> own = kept_vectors;
      for (auto& v : own)
        for (std::size_t i = 0; i < n_obj; ++i) v[i] *= base.objective_scales()[i];
      summary = summarize_front(own, {}, ledger.feasible_objectives(), result.evaluations);
    }
    summary.requested = spec.pareto.points;
    if (result.front.size() < spec.pareto.points) summary.shortfall = std::move(shortfall);
    result.front_summary = std::move(summary);
  }
  if (ledger.stopped()) {
    status = StudyStatus::kStopped;
  } else if (result.front.empty()) {
    status = ledger.any_ok() ? StudyStatus::kNoFeasiblePoint : StudyStatus::kAllFailed;
  } else {
    status = runs.size() == 1 && !statuses.empty() ? statuses[0] : StudyStatus::kOk;
  }
  return status;
}

}  // namespace rackopt::study
